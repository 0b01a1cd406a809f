# The stochastic area of the engines: per-run random streams and firing-date distributions (GSL).
list(APPEND ENGINES_SOURCES
  stochastic/random_stream.cpp
  stochastic/distributions.cpp)
list(APPEND ENGINES_SOURCES stochastic/date_planner.cpp)
