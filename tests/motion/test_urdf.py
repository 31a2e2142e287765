"""Chain.from_urdf and read_inertials: exact numbers, the angle policy, refusals, hostile XML."""

from __future__ import annotations

import inspect
import re
import warnings
from pathlib import Path

import pytest
from sympy import ImmutableMatrix, Matrix, Rational, cos, pi, sin, sqrt, symbols

from screwsym import Chain, Transform, Twist, lambdify

pytest.importorskip("defusedxml")

from screwsym.motion.angles import RecognisedAngle, RecognisedAngleWarning  # noqa: E402
from screwsym.motion.urdf import (  # noqa: E402
    TWO_LINK_URDF,
    path_joints,
    read_inertials,
    urdf_twists_and_home,
)

pytestmark = pytest.mark.filterwarnings("ignore::screwsym.motion.angles.RecognisedAngleWarning")

DATA = Path(__file__).parent.parent / "data" / "urdf"
PANDA = DATA / "panda.urdf"


def robot(joints: str) -> str:
    """A URDF with the given joint elements and the links they name (but the link "zz")."""
    used = sorted(set(re.findall(r'link="(\w+)"', joints)) - {"zz"})
    names = "".join(f'<link name="{n}"/>' for n in used)
    return f'<robot name="r">{names}{joints}</robot>'


def joint(name, kind, parent, child, origin="", extra=""):
    return (f'<joint name="{name}" type="{kind}"><parent link="{parent}"/><child link="{child}"/>'
            f"{origin}{extra}</joint>")


def test_numbers_are_read_exactly_from_their_text():
    text = robot(joint("j", "revolute", "a", "b", '<origin xyz="0.089159 2.7518e-02 -.5"/>',
                       '<axis xyz="0 0 1"/>'))
    chain = Chain.from_urdf(text)
    assert chain.home.p == ImmutableMatrix([Rational(89159, 10**6), Rational(13759, 500000), Rational(-1, 2)])
    # not through a float: 0.1 is 1/10, not 3602879701896397/36028797018963968
    chain = Chain.from_urdf(robot(joint("j", "prismatic", "a", "b", '<origin xyz="0.1 0 0"/>')))
    assert chain.home.p[0] == Rational(1, 10)
    assert chain.twists == (Twist([0, 0, 0], [1, 0, 0]),)  # the default axis is 1 0 0


def test_origins_rpy_axes_and_joint_kinds():
    """rpy is fixed-axis X-Y-Z: R = Rz(y) Ry(p) Rx(r) (the URDF specification); a joint turns about
    its axis through its frame's origin; continuous is revolute; fixed joints fold in."""
    r, p, y = Rational("0.3"), Rational("-0.25"), Rational("1.25")
    text = robot(
        joint("j1", "continuous", "a", "b", '<origin xyz="1 2 3" rpy="0.3 -0.25 1.25"/>', '<axis xyz="0 1 0"/>')
        + joint("f", "fixed", "b", "c", '<origin xyz="0 0 1"/>')
        + joint("j2", "prismatic", "c", "d", "", '<axis xyz="0 0 -1"/>'))
    chain = Chain.from_urdf(text, tip="d")
    Rz = Matrix([[cos(y), -sin(y), 0], [sin(y), cos(y), 0], [0, 0, 1]])
    Ry = Matrix([[cos(p), 0, sin(p)], [0, 1, 0], [-sin(p), 0, cos(p)]])
    Rx = Matrix([[1, 0, 0], [0, cos(r), -sin(r)], [0, sin(r), cos(r)]])
    R = Rz * Ry * Rx
    o = Matrix([1, 2, 3])
    w1 = R * Matrix([0, 1, 0])
    assert (chain.twists[0].omega - w1).expand() == Matrix([0, 0, 0])
    assert (chain.twists[0].v_O - o.cross(w1)).expand() == Matrix([0, 0, 0])
    assert (chain.twists[1].omega).is_zero_matrix
    assert (chain.twists[1].v_O + R[:, 2]).expand() == Matrix([0, 0, 0])
    assert (chain.home.p - (o + R[:, 2])).expand() == Matrix([0, 0, 0])
    assert path_joints(text, tip="d") == ("j1", "j2")
    # a non-unit axis is divided by its exact length
    unit = Chain.from_urdf(robot(joint("j", "revolute", "a", "b", "", '<axis xyz="1 1 0"/>')))
    assert unit.twists[0].omega == ImmutableMatrix([1, 1, 0]) / sqrt(2)


def test_the_angle_policy():
    """Default "pi/12": an rpy decimal that prints a multiple of pi/12 to four or more places is
    that multiple, reported on the chain and in a RecognisedAngleWarning; "exact" keeps the
    decimal as written; a near miss (1.57: two places) is kept with a UserWarning naming the
    joint; lengths are never changed."""
    text = robot(joint("j", "revolute", "a", "b", '<origin xyz="1.5707963267948966 0 0" '
                       'rpy="1.5707963267948966 0.5235987755982988 0.1"/>'))
    exact = Chain.from_urdf(text, angles="exact")
    assert exact.home.R[2, 2] == cos(Rational("1.5707963267948966")) * cos(Rational("0.5235987755982988"))
    assert exact.recognised == ()
    with pytest.warns(RecognisedAngleWarning, match=r"<joint name='j'>: <origin rpy> roll: "
                      r"1\.5707963267948966 -> pi/2; <joint name='j'>: <origin rpy> pitch: "
                      r"0\.5235987755982988 -> pi/6 \(angles='exact' keeps"):
        snapped = Chain.from_urdf(text)
    assert snapped.recognised == (
        RecognisedAngle("1.5707963267948966", "<joint name='j'>: <origin rpy> roll", pi / 2),
        RecognisedAngle("0.5235987755982988", "<joint name='j'>: <origin rpy> pitch", pi / 6))
    assert isinstance(snapped.recognised, tuple) and issubclass(RecognisedAngleWarning, UserWarning)
    with pytest.raises(AttributeError):
        snapped.recognised = ()  # a property: the record cannot be replaced
    x = Rational("1.5707963267948966")
    assert snapped.home.p == ImmutableMatrix([x, 0, 0])  # a length is never recognised
    # roll pi/2, pitch pi/6; yaw 0.1 is not near a multiple of pi/12 and stays 1/10
    expected = Transform.rotation([0, 0, 1], Rational(1, 10)) @ Transform.rotation([0, 1, 0], pi / 6) \
        @ Transform.rotation([1, 0, 0], pi / 2)
    assert (snapped.home.R - expected.R).expand() == Matrix.zeros(3, 3)
    # 1.5708 (four places: round(pi/2, 4)) and -1.5707963 are pi/2 and -pi/2; 1.5709 is not
    for written, value in (("1.5708", pi / 2), ("-1.5707963", -pi / 2), ("1.5709", Rational("1.5709")),
                           ("1.57080", pi / 2), ("1.57070", Rational("1.5707"))):
        one = robot(joint("j", "revolute", "a", "b", f'<origin rpy="{written} 0 0"/>'))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            chain = Chain.from_urdf(one)
        assert (chain.home.R[1, 1] - cos(value)).expand() == 0, written
        assert len(chain.recognised) == (0 if value.is_Rational else 1)
    # 1.57 is round(pi/2, 2), but two places are too few to tell pi/2 from a designer's 1.57:
    # kept as written, and said
    near = robot(joint("j", "revolute", "a", "b", '<origin rpy="1.57 0 0"/>'))
    with pytest.warns(UserWarning, match=r"<joint name='j'>: <origin rpy> roll: the angle 1\.57 is "
                      r"8\.0e-04 from pi/2 but is not a printing of it to 4 or more decimal places"):
        kept = Chain.from_urdf(near)
    assert kept.home.R[1, 1] == cos(Rational(157, 100)) and kept.recognised == ()
    # a tolerance, stated, replaces the printed-precision rule: 1.57 within 1e-3 is pi/2
    with warnings.catch_warnings():
        warnings.simplefilter("error", UserWarning)
        warnings.simplefilter("ignore", RecognisedAngleWarning)
        assert Chain.from_urdf(near, angle_tol=Rational(9, 10**4)).home.R[1, 1] == 0
        assert Chain.from_urdf(text, angles="pi/4").home.R != snapped.home.R
    for bad, match in [("pi/0", "angles: expected 'exact' or 'pi/N'"), ("round", "angles: expected"),
                       ("2*pi/12", "angles: expected"), ("pi/١٢", "angles: expected")]:
        with pytest.raises(ValueError, match=match):
            Chain.from_urdf(text, angles=bad)
    with pytest.raises(TypeError, match="angles: expected 'exact' or 'pi/N'"):
        Chain.from_urdf(text, angles=12)
    with pytest.raises(ValueError, match=r"angle_tol: expected a number in \(0, 1/1000\)"):
        Chain.from_urdf(text, angles="pi/12", angle_tol=Rational(1, 10))


def test_one_warning_per_read_and_each_value_once():
    """read_urdf (what from_urdf uses) parses once and warns once, though the inertials walk the
    joints' origins again; the warning can be silenced by its class."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        chain = Chain.from_urdf(PANDA, base="panda_link0", tip="panda_link8")
    assert [w.category for w in caught] == [RecognisedAngleWarning]
    assert [r.value for r in chain.recognised] == [-pi / 2, pi / 2, pi / 2, -pi / 2, pi / 2, pi / 2]
    assert {r.text for r in chain.recognised} == {"1.5707963267948966", "-1.5707963267948966"}
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        warnings.filterwarnings("ignore", category=RecognisedAngleWarning)
        Chain.from_urdf(PANDA, base="panda_link0", tip="panda_link8")


def test_what_is_refused_names_the_element():
    cases = [
        (robot(joint("slide", "floating", "a", "b")), "b", r"<joint name='slide' type='floating'>: only revolute"),
        (robot(joint("pl", "planar", "a", "b")), "b", r"<joint name='pl' type='planar'>"),
        (robot(joint("j1", "revolute", "a", "b") + joint("m", "revolute", "b", "c", "",
                                                             '<mimic joint="j1"/>')),
         "c", r"<joint name='m' type='revolute'>: a <mimic> joint on the path"),
        (robot(joint("j1", "revolute", "a", "b") + joint("j2", "revolute", "a", "c")
               + joint("j3", "revolute", "b", "d") + joint("loop", "revolute", "c", "d")),
         "d", r"<link name='d'>: the child of 2 joints \['j3', 'loop'\] \(a closed loop\)"),
        (robot(joint("j1", "revolute", "a", "b", '<origin xyz="0 0 1/2"/>')), "b",
         r"<joint name='j1'>: <origin xyz>: expected a decimal number, got '1/2'"),
        (robot(joint("j1", "revolute", "a", "b", '<origin xyz="0 0 __import__"/>')), "b",
         r"expected a decimal number, got '__import__'"),
        (robot(joint("j1", "revolute", "a", "b", '<origin xyz="0 nan 0"/>')), "b", "got 'nan'"),
        (robot(joint("j1", "revolute", "a", "zz")), "b", r"<joint name='j1'>: no <link> named 'zz'"),
        (robot(joint("j1", "revolute", "a", "b", "", '<axis xyz="0 0 0"/>')), "b", "expected a non-zero axis"),
        (robot(joint("j1", "fixed", "a", "b")), "b", "has no moving joint"),
        (robot(joint("j1", "revolute", "a", "b")), "zz", "tip: no <link> named 'zz'"),
        (robot(joint("j1", "revolute", "a", "b") + joint("j2", "revolute", "a", "c")), "c", None),
        ('<rob name="x"/>', None, "expected a <robot> root element, got <rob>"),
    ]
    for text, tip, match in cases:
        if match is None:  # a sibling branch is fine
            assert Chain.from_urdf(text, tip=tip).n_joints == 1
            continue
        with pytest.raises(ValueError, match=match):
            Chain.from_urdf(text, tip=tip)
    with pytest.raises(ValueError, match=r"tip: the link 'a' is not below the link 'b'"):
        Chain.from_urdf(robot(joint("j1", "revolute", "a", "b")), base="b", tip="a")
    with pytest.raises(ValueError, match=r"tip: the file has 2 leaf links"):
        Chain.from_urdf(robot(joint("j1", "revolute", "a", "b") + joint("j2", "revolute", "a", "c")))
    with pytest.raises(TypeError, match="source: expected a URDF file path or its XML text, got int"):
        Chain.from_urdf(3)


def test_a_mimic_joint_off_the_path_is_fine():
    """The Panda's finger joint 2 mimics finger joint 1; the arm's chain does not pass there."""
    chain = Chain.from_urdf(PANDA, base="panda_link0", tip="panda_hand_tcp", angles="pi/12")
    assert chain.n_joints == 7
    with pytest.raises(ValueError, match=r"<joint name='panda_finger_joint2' type='prismatic'>: a <mimic>"):
        Chain.from_urdf(PANDA, base="panda_link0", tip="panda_rightfinger")


def test_the_panda_urdf_is_franka_s_modified_dh_table():
    """Franka Emika's published modified-DH table (Franka Control Interface documentation,
    "Robot and interface specifications": a, d, alpha; the flange is d = 0.107 along z_7)
    gives exactly the chain of panda.urdf from panda_link0 to panda_link8 (the flange), with
    the file's rpy decimals of pi/2 read as pi/2 (the default, angles="pi/12").  The base frames agree and
    the flange transform is Tz(0.107): no other constant transform."""
    rows = [(0, 0, "0.333"), (0, "-pi/2", 0), (0, "pi/2", "0.316"), ("0.0825", "pi/2", 0),
            ("-0.0825", "-pi/2", "0.384"), (0, "pi/2", 0), ("0.088", "pi/2", 0)]

    def value(entry):
        if entry in ("pi/2", "-pi/2"):
            return pi / 2 if entry == "pi/2" else -pi / 2
        return Rational(entry)

    table = [(value(a), value(alpha), value(d), 0) for a, alpha, d in rows]
    dh = Chain.from_dh(table, "modified", tool=Transform.translation([0, 0, Rational("0.107")]))
    urdf = Chain.from_urdf(PANDA, base="panda_link0", tip="panda_link8", angles="pi/12")
    assert urdf == dh
    # and the check can fail: the exact reading of the decimals is close to it but not equal
    exact = Chain.from_urdf(PANDA, base="panda_link0", tip="panda_link8", angles="exact")
    assert exact != dh
    assert max(abs(float(e)) for e in (exact.home.matrix - dh.home.matrix)) < 1e-15


def test_hostile_xml_is_refused():
    """defusedxml refuses entity declarations: an external entity (XXE) and a billion-laughs
    bomb raise before anything is expanded or read."""
    from defusedxml import DefusedXmlException

    xxe = ('<?xml version="1.0"?><!DOCTYPE robot [<!ENTITY x SYSTEM "file:///etc/passwd">]>'
           '<robot name="&x;"><link name="a"/></robot>')
    lol = '<!ENTITY a0 "lol">' + "".join(
        f'<!ENTITY a{i} "{("&a" + str(i - 1) + ";") * 10}">' for i in range(1, 10))
    bomb = f'<?xml version="1.0"?><!DOCTYPE robot [{lol}]><robot name="&a9;"><link name="a"/></robot>'
    for text in (xxe, bomb):
        with pytest.raises(DefusedXmlException):
            Chain.from_urdf(text)
        with pytest.raises(DefusedXmlException):
            read_inertials(text)


def test_names_are_data_never_code():
    """A robot, link or joint name with code in it stays a string: it reaches error messages and
    read_inertials' records, never generated source (there is no code generation here, and the
    chain holds only numbers: lambdify's source has no trace of the names)."""
    evil = "x\"); __import__('os').system('echo pwned'); (\""
    esc = evil.replace('"', "&quot;")
    text = (f'<robot name="{esc}"><link name="{esc}"/><link name="b"/>'
            f'<joint name="{esc}" type="revolute"><parent link="{esc}"/><child link="b"/></joint></robot>')
    chain = Chain.from_urdf(text)
    assert not any(isinstance(a, str) for a in chain.atoms())
    q = symbols("q", real=True)
    f = lambdify([q], chain.forward([q]).matrix, names=["q"])
    assert "import" not in inspect.getsource(f) and "pwned" not in inspect.getsource(f)
    assert read_inertials(text)[0].joint == evil
    with pytest.raises(ValueError) as info:
        Chain.from_urdf(text, tip="nope")
    assert repr(evil) in str(info.value)


def test_read_inertials_merges_and_moves_to_the_space_frame():
    """Two links rigidly joined (one off the path) merge by Steiner's theorem; a massless link
    adds nothing; com = T c, inertia = R I R^T in the space frame at home."""
    inertial = ('<inertial><origin xyz="{c}" rpy="{rpy}"/><mass value="{m}"/>'
                '<inertia ixx="{i[0]}" ixy="0" ixz="0" iyy="{i[1]}" iyz="0" izz="{i[2]}"/></inertial>')
    links = (f'<link name="b">{inertial.format(c="0 0 1", rpy="0 0 0", m=1, i=(1, 2, 3))}</link>'
             f'<link name="c">{inertial.format(c="1 0 0", rpy="0 0 1.5707963267948966", m=3, i=(1, 2, 3))}</link>'
             '<link name="e"><inertial><mass value="0"/></inertial></link>')
    names = "".join(f'<link name="{n}"/>' for n in "adf")
    text = (f'<robot name="r">{names}{links}'
            + joint("j1", "revolute", "a", "b", '<origin xyz="2 0 0" rpy="0 0 1.5707963267948966"/>')
            + joint("fc", "fixed", "b", "c", '<origin xyz="0 0 1"/>')
            + joint("fe", "fixed", "b", "e")
            + joint("j2", "revolute", "b", "d") + joint("fd", "fixed", "d", "f") + "</robot>")
    (body, last) = read_inertials(text, tip="f", angles="pi/12")
    assert body.joint == "j1" and body.links == ("b", "c", "e") and body.mass == 4
    # frames: b at (2,0,0) turned +90 deg about z; b's com (2,0,1); c's com: b + Rz (1,0,1) = (2,1,1)
    assert body.com == ImmutableMatrix([2, Rational(3, 4), 1])
    # b's inertia turned by Rz(90): diag(2,1,3); c's by Rz(180): diag(1,2,3); Steiner about the com
    d_b, d_c = Matrix([0, -Rational(3, 4), 0]), Matrix([0, Rational(1, 4), 0])
    steiner = sum((m * (d.dot(d) * Matrix.eye(3) - d * d.T) for m, d in ((1, d_b), (3, d_c))), Matrix.zeros(3, 3))
    assert body.inertia == ImmutableMatrix(Matrix.diag(2, 1, 3) + Matrix.diag(1, 2, 3) + steiner)
    assert last.joint == "j2" and last.mass == 0 and last.com == ImmutableMatrix([0, 0, 0])
    with pytest.raises(ValueError, match=r"<link name='b'>: <inertial> <mass value>: expected a mass >= 0"):
        read_inertials(text.replace('<mass value="1"/>', '<mass value="-1"/>'), tip="f")


def test_the_doctest_robot_and_files():
    twists, home = urdf_twists_and_home(TWO_LINK_URDF, angles="pi/12")
    assert Chain(twists, home) == Chain.from_urdf(TWO_LINK_URDF, angles="pi/12")
    assert Chain.from_urdf(str(PANDA), "panda_link0", "panda_link8", angles="pi/12") == \
        Chain.from_urdf(PANDA.read_bytes(), "panda_link0", "panda_link8", angles="pi/12")


def test_without_defusedxml_the_error_says_how_to_install(monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "defusedxml.ElementTree", None)
    with pytest.raises(ImportError, match=r'pip install -e "\.\[urdf\]"'):
        Chain.from_urdf(TWO_LINK_URDF)


# ----------------------------------------------------------- bad files: refused quickly, clearly
ARM = robot(joint("j", "revolute", "a", "b", '<origin xyz="{xyz}" rpy="{rpy}"/>', '<axis xyz="0 0 1"/>'))


def arm(xyz="0 0 0", rpy="0 0 0"):
    return ARM.replace("{xyz}", xyz).replace("{rpy}", rpy)


def test_numbers_have_exponent_and_length_limits():
    """A 12-character 1e99999999 would be a 100-million-digit integer; a 5000-digit number is
    no length: both refused at once, naming the element (the limits are shown to let the
    largest allowed through)."""
    from screwsym.motion.urdf import MAX_EXPONENT, MAX_NUMBER_CHARS

    for bad, match in [("1e99999999", "exponent of at most 300"), ("1" * 5000, "at most 100 characters"),
                       ("0.000e400", "exponent"), ("1E-99999999", "exponent")]:
        with pytest.raises(ValueError, match=rf"<joint name='j'>: <origin xyz>: expected a decimal .*{match}"):
            Chain.from_urdf(arm(xyz=f"{bad} 0 0"))
    assert Chain.from_urdf(arm(xyz=f"1e{MAX_EXPONENT} 0 0")).home.p[0] == 10**MAX_EXPONENT
    assert Chain.from_urdf(arm(xyz=f"{'1' * MAX_NUMBER_CHARS} 0 0")).home.p[0] == int("1" * MAX_NUMBER_CHARS)
    # an rpy of 1e999 with the default angles: a ValueError (was OverflowError); 1e300 is kept
    with pytest.raises(ValueError, match=r"<joint name='j'>: <origin rpy> roll: expected a decimal exponent"):
        Chain.from_urdf(arm(rpy="1e999 0 0"))
    for tol in (None, Rational(1, 10**6)):
        assert Chain.from_urdf(arm(rpy="9999999999e300 0 0"), angle_tol=tol).recognised == ()


def test_only_ascii_digits():
    for bad in ("١٢", "１", "1.5٧", "٣e2"):
        with pytest.raises(ValueError, match=r"<origin xyz>: expected a decimal number, got"):
            Chain.from_urdf(arm(xyz=f"{bad} 0 0"))
        with pytest.raises(ValueError, match=r"<origin rpy> pitch: expected a decimal number, got"):
            Chain.from_urdf(arm(rpy=f"0 {bad} 0"))
    assert Chain.from_urdf(arm(xyz="12 0 0")).home.p[0] == 12


def test_a_cycle_or_a_link_with_two_parents_below_the_path_is_refused():
    """The cycle of fixed joints that made read_inertials loop forever, and a link with two
    parents off the path that was counted twice (mass 5 instead of 4), are refused, naming the
    link (urdfdom refuses such files too); the same file without the second parent reads 4."""
    mass = '<inertial><mass value="{m}"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial>'
    links = (f'<link name="a"/><link name="b">{mass.format(m=1)}</link><link name="c">{mass.format(m=1)}</link>'
             f'<link name="d">{mass.format(m=1)}</link><link name="e">{mass.format(m=1)}</link><link name="t"/>')

    def file(*joints):
        return f'<robot name="r">{links}{"".join(joints)}</robot>'

    path = [joint("j", "revolute", "a", "b"), joint("k", "revolute", "b", "t")]
    good = file(*path, joint("f1", "fixed", "b", "c"), joint("f2", "fixed", "c", "d"),
                joint("f3", "fixed", "b", "e"))
    assert read_inertials(good, tip="t")[0].mass == 4
    twice = file(*path, joint("f1", "fixed", "b", "c"), joint("f2", "fixed", "c", "d"),
                 joint("f3", "fixed", "b", "e"), joint("f4", "fixed", "e", "d"))
    cycle = file(*path, joint("f1", "fixed", "b", "c"), joint("f2", "fixed", "c", "d"),
                 joint("f3", "fixed", "d", "c"))
    for text in (twice, cycle):
        with pytest.raises(ValueError, match=r"<link name='[cd]'>: the child of 2 joints"):
            read_inertials(text, base="a", tip="t")
        with pytest.raises(ValueError, match=r"the child of 2 joints"):
            Chain.from_urdf(text, base="a", tip="t", inertias=True)
    # a cycle that returns to the path: refused on the path itself
    back = file(*path, joint("f1", "fixed", "b", "c"), joint("f2", "fixed", "c", "b"))
    with pytest.raises(ValueError, match=r"<link name='b'>: the child of 2 joints"):
        read_inertials(back, base="a", tip="t")


def test_a_path_is_a_path_and_xml_text_is_text(tmp_path):
    import time

    start = time.process_time()
    for bad, match in [("/dev/zero", "expected a regular file, got '/dev/zero'"),
                       (str(tmp_path), "expected a regular file"),
                       ("", "expected a URDF file path or its XML text, got an empty string"),
                       ("   ", "expected a URDF file path or its XML text, got an empty string"),
                       (str(tmp_path / "missing.urdf"), "no URDF file at"),
                       ("robot name='x'><link/>", "expected a URDF file path or XML text starting with '<'")]:
        with pytest.raises(ValueError, match=rf"source: {match}"):
            Chain.from_urdf(bad)
    assert time.process_time() - start < 5  # /dev/zero is never read
    with pytest.raises(ValueError, match="source: expected a regular file"):
        Chain.from_urdf(Path("/dev/zero"))
    with pytest.raises(ValueError, match="source: not well-formed XML"):
        Chain.from_urdf("<robot")
    with pytest.raises(TypeError, match="source: expected a URDF file path or its XML text, got int"):
        Chain.from_urdf(3)
    big = tmp_path / "big.urdf"
    with big.open("wb") as f:
        f.truncate(65 * 2**20)  # sparse: 65 MB of nothing
    with pytest.raises(ValueError, match=r"has 68157440 bytes, more than 67108864"):
        Chain.from_urdf(big)
    # a BOM or white space before the XML is text, not a path
    want = Chain.from_urdf(TWO_LINK_URDF)
    for text in ("\ufeff" + TWO_LINK_URDF, "  \n\t" + TWO_LINK_URDF, "\ufeff\n" + TWO_LINK_URDF):
        assert Chain.from_urdf(text) == want
        assert Chain.from_urdf(text.encode("utf-8")) == want
        f = tmp_path / "x.urdf"
        f.write_text(text, encoding="utf-8")
        assert Chain.from_urdf(f) == want and Chain.from_urdf(str(f)) == want


def test_encodings_from_the_xml_declaration(tmp_path):
    """UTF-16 and latin-1 files (bytes, or a path) are decoded as their declaration says: a link
    name with an accent comes through."""
    text = TWO_LINK_URDF.replace('"upper"', '"épaule"')
    want = Chain.from_urdf(text)
    for encoding in ("utf-16", "latin-1", "utf-8"):
        data = f'<?xml version="1.0" encoding="{encoding}"?>\n{text}'.encode(encoding)
        assert Chain.from_urdf(data) == want
        f = tmp_path / f"{encoding}.urdf"
        f.write_bytes(data)
        assert Chain.from_urdf(f) == want
        assert read_inertials(f)[0].links == ("épaule",)
    # and a wrong declaration is an error, not a silent misreading
    with pytest.raises(ValueError, match="source: not well-formed XML"):
        Chain.from_urdf(f'<?xml version="1.0" encoding="utf-8"?>{text}'.encode("utf-16"))


def test_the_shipped_robot_files_are_found_from_any_directory(tmp_path, monkeypatch):
    """sample_urdf reaches the files through the package (importlib.resources), wherever the
    process runs; they are the files the tests read (tests/data/urdf), byte for byte."""
    from screwsym.motion.urdf import SAMPLES, sample_urdf

    monkeypatch.chdir(tmp_path)
    for name in SAMPLES:
        path = sample_urdf(name)
        assert path.is_absolute() and path.read_bytes() == (DATA / name).read_bytes()
    assert Chain.from_urdf(sample_urdf("panda.urdf"), "panda_link0", "panda_link8").n_joints == 7
    with pytest.raises(ValueError, match=r"name: expected one of \('panda.urdf', 'ur5_robot.urdf'\)"):
        sample_urdf("../../etc/passwd")
