# value cdf
1 0
2 0.25
4 0.75
8 1
