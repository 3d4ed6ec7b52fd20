"""The rig's full state (checkpoints) and the closed loop's linearisation
(issue 25, item 1's second half)."""
import math
import warnings

import numpy as np
import pytest

import rollerrig as rr
from rollerrig import _core
from rollerrig import RollerRigError


def _rig():
    return rr.build_rig()[0]


def _refs(rig, n, xi=0.02):
    w = 5.0 / rig.info.roller_radius
    return np.full(n, w), np.full(n, xi)


def test_full_state_names_and_values():
    rig = _rig()
    s = rig.full_state()
    assert list(s)[:3] == ["t", "x", "y"] and len(s) == 35
    # the plant's part is the plant's vector, bit for bit
    plant = [s[n] for n in ("x", "y", "yaw", "chi", "theta_r", "vx", "vy", "yaw_rate", "spin",
                            "roller_spin", "torque_roller", "torque_wheelset")]
    assert np.array_equal(plant, rig.y) and s["t"] == rig.t
    assert s["creep_control"] == 0.0 and math.isnan(s["xi_ref"])


def test_checkpoint_bit_for_bit():
    """get -> 60 samples -> set back -> the same 60 samples, bit for bit,
    with the creepage controller running (its K, the PI integrals and the
    encoders' counts all in play); a changed value changes the run."""
    rig = _rig()
    r, x = _refs(rig, 200)
    rec0, st = rig.run(r[:40], x[:40])
    assert st >= 0
    saved = rig.full_state()
    assert saved["creep_control"] == 1.0 and saved["roller_enc_primed"] == 1.0
    a, st = rig.run(r[:60], x[:60])
    assert st >= 0
    assert rig.set_full_state(saved) >= 0
    b, st = rig.run(r[:60], x[:60])
    assert st >= 0
    assert np.array_equal(a, b)               # the NaN-free record: exact equality
    changed = dict(saved, creepctl_K=saved["creepctl_K"] - 0.01)
    assert rig.set_full_state(changed) >= 0
    c, _ = rig.run(r[:60], x[:60])
    i = [f[0] for f in _core.RIG_RECORD].index("spin")
    assert a[-1, i] != c[-1, i]


def test_set_full_state_refusals():
    rig = _rig()
    s = rig.full_state()
    before = rig.full_state()
    with pytest.raises(RollerRigError, match="must be a dict"):
        rig.set_full_state(list(s.values()))
    with pytest.raises(RollerRigError, match=r"lacks \['t'\]"):
        rig.set_full_state({k: v for k, v in s.items() if k != "t"})
    with pytest.raises(RollerRigError, match="unknown names"):
        rig.set_full_state(dict(s, bogus=1.0))
    with pytest.raises(RollerRigError, match=r"state\['vy'\] must be a real number"):
        rig.set_full_state(dict(s, vy="fast"))
    assert rig.set_full_state(dict(s, vy=math.nan)) == -1            # RR_ERR_NONFINITE
    assert rig.set_full_state(dict(s, creep_control=2.0)) == -9      # RR_ERR_PARAM
    assert rig.set_full_state(dict(s, wheelset_count=0.5)) == -9
    assert rig.set_full_state(dict(s, y=0.02)) == -3                 # the wheel off its roller
    assert rig.full_state() == pytest.approx(before, nan_ok=True)    # nothing changed
    rig.sample(*[v[0] for v in _refs(rig, 1)])
    with pytest.raises(RollerRigError, match="Rig.full_state"):
        rig.full_state()


# ---- the closed loop linearised (rr.linearize(closed_loop=True)) ----------

FINE = {"roller_drive": {"encoder_counts_per_rev": 2**30},
        "wheelset_drive": {"encoder_counts_per_rev": 2**30}}


@pytest.fixture(scope="module")
def loop():
    return rr.linearize(closed_loop=True)


def test_closed_loop_shape_and_modes(loop):
    assert loop.A.shape == (14, 14) and len(loop.states) == 14
    assert loop.T == pytest.approx(0.004) and loop.roller_speed == pytest.approx(5.0)
    assert np.all(np.diff(np.abs(loop.z)) <= 0)
    assert np.allclose(loop.eigenvalues, np.log(loop.z.astype(complex)) / loop.T)
    # the default gains are stable at 4 ms (rr_rig_check asks it of each drive alone)
    assert loop.spectral_radius < 1
    # the slowest modes are the PI integrals', the lateral shift's next
    assert loop.modes[0].dominant[0] == "wheelset_pi_integral"
    assert any(m.dominant[0] == "y" for m in loop.modes)


def _coords(full, info, names):
    """The closed loop's coordinates `names` of a full state (closed_loop.STATES)."""
    q = (2 * math.pi / info.roller_counts, 2 * math.pi / info.wheelset_counts)
    c = dict(full, roller_angle_since_count=full["theta_r"] - full["roller_count"] * q[0],
             wheelset_angle_since_count=full["chi"] - full["wheelset_count"] * q[1])
    return np.array([c[k] for k in names])


def _kick_decay(loop, make_rig, kick, xi=math.nan, twin=True, spans=(100, 300)):
    """The dominant mode's decay per sample in the nonlinear quantised rig:
    the full state `loop.full_state` with `kick` (names: changes) added, run
    spans[0] then spans[1] samples at the loop's roller speed (and creepage
    target xi), the perturbation (less an unkicked twin's run, or less the
    fixed point) projected on the dominant left eigenvector; and log|z|."""
    z, V = np.linalg.eig(loop.A)
    k = int(np.argmax(np.abs(z)))
    w = np.linalg.inv(V)[k]
    kicked = dict(loop.full_state, **{n: loop.full_state[n] + d for n, d in kick.items()})
    rigs = [make_rig(), make_rig()] if twin else [make_rig()]
    starts = [loop.full_state, kicked] if twin else [kicked]
    for rig, s in zip(rigs, starts):
        assert rig.set_full_state(s) >= 0
    wr = loop.full_state["roller_spin"] if loop.track else \
        loop.roller_speed / rigs[0].info.roller_radius
    c = []
    for n in spans:
        x = []
        for rig in rigs:
            _, st = rig.run(np.full(n, wr), np.full(n, xi))
            assert st >= 0
            x.append(_coords(rig.full_state(), rig.info, loop.states))
        c.append(abs(w @ (x[-1] - (x[0] if twin else loop.state))))
    return math.log(c[1] / c[0]) / spans[1], math.log(abs(z[k]))


def test_closed_loop_decay_matches_dominant_z(loop):
    """A kick of 0.5 N m on the wheelset PI's integral, run by the nonlinear
    rig with its quantised encoders beside an unkicked twin (their
    difference is the perturbation: the settled state's own creep, 1e-9 of
    a scale per 2000 samples, cancels): the dominant mode's amplitude (the
    difference's projection on its left eigenvector) decays from sample 100
    to 400 at the rate log|z| per sample within 1 % (measured 4e-4; the
    other modes, |z| <= 0.9932, have fallen by 0.3 or more there, and one
    count of jitter, 2e-4 rad/s, is 1e-3 of the amplitude)."""
    rate, ref = _kick_decay(loop, _rig, {"wheelset_pi_integral": 0.5})
    assert rate == pytest.approx(ref, rel=1e-2)


def test_closed_loop_on_track():
    """On track the rails' held speed and the roller drive (which acts on
    nothing there) are not coordinates, and the rail's speed is rounded to
    whole counts of its encoder a sample (closed_loop._track_loop: with the
    2^31 - 1 counts a turn of the 1000 m rail the reading otherwise
    alternates by a count, 1.5e-4 of the speed, and forces the loop at the
    sample rate).  The loop then settles to a steady state (vx there
    measured 4e-6 m/s, over 3000 samples std 2.9e-6 m/s, the wheelset
    encoder's count jitter; before, the block ends showed -8e-5 m/s: the
    forced cycle, vx std 1.2e-4 m/s, mean 3e-8 m/s); the same 0.5 N m
    kick's dominant mode (the wheelset PI integral's, |z| = 0.99668)
    decays at log|z| within 1 % (measured 3.7e-3)."""
    lt = rr.linearize(track=True, closed_loop=True)
    assert lt.track and len(lt.states) == 11
    assert not {"roller_spin", "torque_roller", "roller_pi_integral"} & set(lt.states)
    assert lt.roller_speed == pytest.approx(5.0, rel=1e-4)
    assert lt.spectral_radius < 1
    assert abs(lt.full_state["vx"]) < 2e-5
    rate, ref = _kick_decay(lt, lambda: rr.build_rig(track=True)[0],
                            {"wheelset_pi_integral": 0.5})
    assert rate == pytest.approx(ref, rel=1e-2)
    # at 20 m/s the rail encoder's angle since a count is read exactly (z = 0):
    # its mode at -inf /s, damping 1, without a warning
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fast = rr.linearize(track=True, closed_loop=True, roller_speed=20.0)
    gone = fast.modes[-1]
    assert gone.z == 0 and gone.eigenvalue.real == -math.inf and gone.damping_ratio == 1.0
    assert fast.spectral_radius < 1
    # its own steady state given back: accepted, the same matrix and speed
    again = rr.linearize(track=True, closed_loop=True, state=lt.full_state)
    assert np.array_equal(again.A, lt.A) and again.roller_speed == lt.roller_speed


def _on_mode(loop, x, info):
    """The full state of the loop's coordinates x (closed_loop.STATES)."""
    q = (2 * math.pi / info.roller_counts, 2 * math.pi / info.wheelset_counts)
    s = dict(loop.full_state)
    for name, v in zip(loop.states, x):
        if name == "roller_angle_since_count":
            s["theta_r"] = s["roller_count"] * q[0] + v
        elif name == "wheelset_angle_since_count":
            s["chi"] = s["wheelset_count"] * q[1] + v
        else:
            s[name] = float(v)
    return s


def test_closed_loop_under_creepage_control():
    """Under the creepage controller (target 0.02): the proportional law's
    linearisation about the creepage at the target (closed_loop._creep_loop)
    against the nonlinear quantised rig.  From the fixed point moved along
    the controller's mode (K's, real, |z| = 0.99032, the second slowest after
    the roller PI integral's) by 3e-4 of creepage on the side short of the
    target, the rig is run 250 samples at the loop's reference: the creepage
    stays short of the target all along (the recovery law never acts: what
    the linearisation is of), and the mode's amplitude (projection on its
    left eigenvector) decays from sample 50 to 250 at log|z| a sample
    within 1 % (measured 9e-6; the creepage 3e-5 short at the end, the
    encoders' jitter 5e-6 of creepage a count).  A kick from the fixed
    point itself would not do: there the creepage sits on the target and
    the first sample takes the recovery law's step (beta = 0.002 of K).  The fixed point is steady (the test
    inside linearize), the controller's K there 1 + sense xi (0.98) to
    1e-9."""
    lc = rr.linearize(closed_loop=True, creepage_target=0.02)
    assert lc.creepage_target == 0.02 and lc.states[-1] == "creepctl_K"
    assert lc.full_state["creep_control"] == 1.0 and lc.full_state["xi_ref"] == 0.02
    rig = _rig()
    info = rig.info
    assert lc.full_state["creepctl_K"] == pytest.approx(1 + info.sense * 0.02, abs=1e-9)
    assert lc.spectral_radius < 1
    again = rr.linearize(closed_loop=True, creepage_target=0.02, state=lc.full_state)
    assert np.array_equal(again.A, lc.A)
    z, V = np.linalg.eig(lc.A)
    W = np.linalg.inv(V)
    kK = lc.states.index("creepctl_K")
    assert [m.dominant[0] for m in lc.modes[:2]] == ["roller_pi_integral", "creepctl_K"]
    for k in np.argsort(-np.abs(z))[1:2]:
        assert z[k].imag == 0
        v = V[:, k].real
        rates = []
        for sign in (1.0, -1.0):
            # on the mode K moves by (z - 1) v_K a sample, which is sense
            # alpha (target - creepage): 3e-4 of creepage
            x0 = lc.state + sign * 3e-4 * info.alpha / abs((z[k].real - 1) * v[kK]) * v
            assert rig.set_full_state(_on_mode(lc, x0, info)) >= 0
            c, dxi = [], []
            for i in range(250):
                _, st = rig.run([lc.roller_reference], [0.02])
                assert st >= 0
                s = rig.full_state()
                dxi.append(s["creepctl_dxi"])
                if i + 1 in (50, 250):
                    c.append(abs(W[k] @ (_coords(s, info, lc.states) - lc.state)))
            if dxi[0] > 0:        # the side short of the target
                assert min(dxi) > 0
                rates.append(math.log(c[1] / c[0]) / 200)
        assert len(rates) == 1
        assert rates[0] == pytest.approx(math.log(abs(z[k])), rel=1e-2)


@pytest.mark.slow
def test_closed_loop_plant_part_against_open_loop():
    """The lateral shift's mode does not involve the drives (the centred
    wheelset: symmetric), so the closed loop's log(z)/T is the plant's
    continuous eigenvalue up to the integrator's error over a step: 0.5 % at
    one step a sample (lambda h = 0.14, TR-BDF2's O((lambda h)^2) relative,
    measured 0.18 %), 5e-4 at 20 steps (lambda h = 0.007; measured 1.3e-4,
    with the simplified-theory Newton model); on track (the rail's speed
    rounded to whole counts, 5e-5 of it) the same 0.5 % at one step
    (measured 0.20 %)."""
    for substeps, tol, track in ((1, 5e-3, False), (20, 5e-4, False), (1, 5e-3, True)):
        P = {"integration": {"substeps": substeps}}
        cl = rr.linearize(P, closed_loop=True, track=track)
        ol = rr.linearize(P, track=track)
        lam = next(m.eigenvalue for m in cl.modes if m.dominant == ("y",))
        ref = next(m.eigenvalue for m in ol.modes if m.dominant == ("y",))
        assert lam.real == pytest.approx(ref.real, rel=tol) and abs(lam.imag) < 1e-9


def test_closed_loop_quantisation(loop):
    """The quantiser at unit gain: the matrix does not depend on the
    encoders' counts (2^23 against 2^30: within 1e-5 of the largest entry,
    measured 4e-7, the fixed points differing by the 2^23 encoder's jitter;
    the dominant z within 1e-5, measured 6e-7), and a coarse encoder whose
    loop hunts at the count level is refused naming the counts."""
    a = loop
    b = rr.linearize(FINE, closed_loop=True)
    assert abs(a.z[0] - b.z[0]) < 1e-5
    assert np.max(np.abs(a.A - b.A)) < 1e-5 * np.max(np.abs(a.A))
    coarse = {"roller_drive": {"encoder_counts_per_rev": 4096},
              "wheelset_drive": {"encoder_counts_per_rev": 4096}}
    with pytest.raises(RollerRigError, match="encoder_counts_per_rev"):
        rr.linearize(coarse, closed_loop=True)


def test_closed_loop_bad_input(loop):
    for bad in ("yes", 1, None):
        with pytest.raises(RollerRigError, match="closed_loop must be True or False"):
            rr.linearize(closed_loop=bad)
    off = dict(loop.full_state, y=loop.full_state["y"] + 1e-4)
    with pytest.raises(RollerRigError, match="state is not steady: .*y by"):
        rr.linearize(closed_loop=True, state=off)
    with pytest.raises(RollerRigError, match="state must be a full state dict"):
        rr.linearize(closed_loop=True, state=loop.state)
    rig = _rig()
    r, x = _refs(rig, 50)
    rig.run(r, x)
    with pytest.raises(RollerRigError, match="under creepage control.*creepage_target"):
        rr.linearize(closed_loop=True, state=rig.full_state())
    with pytest.raises(RollerRigError, match="state must be under creepage control at "
                                             "that target"):
        rr.linearize(closed_loop=True, state=rig.full_state(), creepage_target=0.03)
    with pytest.raises(RollerRigError, match="creepage_target needs closed_loop=True"):
        rr.linearize(creepage_target=0.02)
    for bad in (math.nan, math.inf, 0.5, -0.7, True, "0.02"):
        with pytest.raises(RollerRigError, match="creepage_target must be a finite number"):
            rr.linearize(closed_loop=True, creepage_target=bad)
    # the steady state itself is accepted, and gives the same matrix
    again = rr.linearize(closed_loop=True, state=loop.full_state)
    assert np.allclose(again.A, loop.A, rtol=0, atol=1e-9 * np.max(np.abs(loop.A)))
