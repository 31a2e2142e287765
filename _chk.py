import sys, time; sys.path.insert(0, "tests")
import numpy as np, modern_robotics as mr
from sympy import Float, symbols
from _dynamics import mr_ur5_chain, mr_ur5_lists
arm = mr_ur5_chain(); Mlist, Glist, Slist = mr_ur5_lists()
rng = np.random.default_rng(0); q, qd, qdd = rng.normal(size=(3, 6))
F = lambda v: [Float(x) for x in v]
t = time.time(); tau = arm.inverse_dynamics(F(q), F(qd), F(qdd), gravity=[0, 0, -9.81]); print("float rnea", time.time() - t)
print(np.abs(np.array(tau, float).ravel() - mr.InverseDynamics(q, qd, qdd, [0, 0, -9.81], np.zeros(6), Mlist, Glist, Slist)).max())
t = time.time(); H = arm.mass_matrix(F(q)); print("float M", time.time() - t)
print(np.abs(np.array(H, float) - mr.MassMatrix(q, Mlist, Glist, Slist)).max())
Y = arm.regressor(F(q), F(qd), F(qdd), gravity=[0, 0, -9.81])
pi = np.concatenate([np.array(b.parameters(), float).ravel() for b in arm.inertias])
print("regressor", np.abs(np.array(Y, float) @ pi - np.array(tau, float).ravel()).max())
qs = symbols("q1:7", real=True); us = symbols("u1:7", real=True); ws = symbols("w1:7", real=True)
t = time.time(); H = arm.mass_matrix(qs); print("symbolic M", time.time() - t, sum(e.count_ops() for e in H))
t = time.time(); tau = arm.inverse_dynamics(qs, us, ws, gravity=[0, 0, -Float(9.81)]); print("symbolic ID", time.time() - t, sum(e.count_ops() for e in tau))
