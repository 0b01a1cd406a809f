# response time of the radio link, in ms
2.0 0.0
3.0, 0.25

5.0	0.75   # the bulk
10.0 1.0
