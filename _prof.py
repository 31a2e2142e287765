import sys, time, cProfile, pstats; sys.path.insert(0, "tests")
from sympy import symbols
from _dynamics import mr_ur5_chain
arm = mr_ur5_chain()
qs = symbols("q1:7", real=True)
cProfile.run("arm.mass_matrix(qs)", "/tmp/dyn/prof")
p = pstats.Stats("/tmp/dyn/prof"); p.sort_stats("cumulative").print_stats(35)
