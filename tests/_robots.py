"""Arms with inertias for the dynamics programs and the base parameters: the PUMA 560, the Panda.

The PUMA 560 is Corke's model (Robotics Toolbox ``mdl_puma560`` / ``Puma560``: standard
Denavit–Hartenberg table, link masses, centres of mass and principal inertias of Armstrong,
Khatib & Burdick 1986 as compiled in P. Corke, B. Armstrong-Helouvry, "A search for consensus
among model parameters reported for the PUMA 560 robot", ICRA 1994), every decimal read as the
rational it spells.  The table is kept as published although two of its bodies are not
physical (link 1: no mass and the inertia ``I_yy = 0.35`` alone; link 3: ``0.066 + 0.0125 <
0.086`` breaks the triangle inequality), so the bodies are made without
``SpatialInertia``'s checks (``SpatialInertia._new``, test-only): the dynamics are linear in
the parameters and need no physical body.  The Panda
(7 joints) is read from the URDF of ``example-robot-data`` (tests/data/urdf).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from sympy import ImmutableMatrix, Rational, pi

from screwsym import Chain, SpatialInertia, Transform

DATA = Path(__file__).parent / "data" / "urdf"

#: (a, alpha, d) of each row, theta the joint variable (Corke's standard DH table)
PUMA560_DH = [("0", pi / 2, "0"), ("0.4318", 0, "0"), ("0.0203", -pi / 2, "0.15005"),
              ("0", pi / 2, "0.4318"), ("0", -pi / 2, "0"), ("0", 0, "0")]
#: mass, centre of mass and (I_xx, I_yy, I_zz) about it, in DH frame i
PUMA560_BODIES = [
    ("0", ("0", "0", "0"), ("0", "0.35", "0")),
    ("17.4", ("-0.3638", "0.006", "0.2275"), ("0.13", "0.524", "0.539")),
    ("4.8", ("-0.0203", "-0.0141", "0.070"), ("0.066", "0.086", "0.0125")),
    ("0.82", ("0", "0.019", "0"), ("1.8e-3", "1.3e-3", "1.8e-3")),
    ("0.34", ("0", "0", "0"), ("0.3e-3", "0.4e-3", "0.3e-3")),
    ("0.09", ("0", "0", "0.032"), ("0.15e-3", "0.15e-3", "0.04e-3")),
]


def puma560() -> Chain:
    """Corke's PUMA 560 (standard DH, Armstrong-Khatib-Burdick inertias), exact."""
    rows = [(Rational(a), alpha, Rational(d), 0) for a, alpha, d in PUMA560_DH]
    kin = Chain.from_dh(rows, "standard")
    frames, T = [], Transform.identity()
    for a, alpha, d, _ in rows:
        T = T @ Transform.translation([0, 0, d]) @ Transform.translation([a, 0, 0]) @ \
            Transform.rotation([1, 0, 0], alpha)
        frames.append(T)
    bodies = []
    for m, c, inertia in PUMA560_BODIES:
        I = ImmutableMatrix.diag(*(Rational(x) for x in inertia))
        bodies.append(SpatialInertia._new(Rational(m), ImmutableMatrix([Rational(x) for x in c]), I))
    return Chain(kin.twists, kin.home, bodies, link_frames=frames)


def panda() -> Chain:
    """The Franka Emika Panda's 7 arm joints with their URDF inertias (exact decimals)."""
    return Chain.from_urdf(DATA / "panda.urdf", "panda_link0", "panda_link8", angles="pi/12",
                           inertias=True)


def _frame_on_axis(twist):
    """A frame (R, p) with z along the joint's axis and origin on it (floats)."""
    w, v = (np.array(x, dtype=float).ravel() for x in (twist.omega, twist.v_O))
    revolute = np.linalg.norm(w) > 0
    u = w if revolute else v
    u = u / np.linalg.norm(u)
    a = np.array([1.0, 0, 0]) if abs(u[0]) < 0.9 else np.array([0, 1.0, 0])
    x = np.cross(a, u)
    x /= np.linalg.norm(x)
    R = np.column_stack([x, np.cross(u, x), u])
    p = np.cross(w, v) / (w @ w) if revolute else np.zeros(3)
    return R, p, revolute


def pin_model(pin, chain, gravity=(0.0, 0.0, -9.81)):
    """A pinocchio model of ``chain`` (unit-speed revolute and prismatic joints), test-only.

    Each joint gets a frame on its axis with z along it, and each body is carried into it
    (also the model of tests/crosscheck/test_dynamics_peers.py).
    """
    model = pin.Model()
    parent, Rp, pp = 0, np.eye(3), np.zeros(3)
    for i, (twist, body) in enumerate(zip(chain.twists, chain.inertias, strict=True)):
        R, p, revolute = _frame_on_axis(twist)
        placement = pin.SE3(Rp.T @ R, Rp.T @ (p - pp))
        joint = pin.JointModelRZ() if revolute else pin.JointModelPZ()
        jid = model.addJoint(parent, joint, placement, f"j{i}")
        m = float(body.mass)
        c = np.array(body.com, dtype=float).ravel()
        Ic = np.array(body.inertia, dtype=float)
        model.appendBodyToJoint(jid, pin.Inertia(m, R.T @ (c - p), R.T @ Ic @ R), pin.SE3.Identity())
        parent, Rp, pp = jid, R, p
    model.gravity = pin.Motion(np.array(gravity, dtype=float), np.zeros(3))
    return model
