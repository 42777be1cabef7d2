"""The animation of 3-D results: the GIF's frames against the bodies' positions, the HTML
view drawn by a headless browser, shapes as MSL defines them.

Where a GIF frame draws a body is checked against pixels computed here with numpy from the
simulated joint angles: the parts' positions by closed-form kinematics, the box they fill
over the whole motion from MSL's shape sizes, and the orthographic camera written out
(not ``Animation.project``)."""
import itertools
import os
import subprocess

import numpy as np
import pytest
from PIL import Image

import acausal
from acausal.analysis.animation import Animation, shapes_of
from acausal.components.multibody import BodyBox, World
from acausal.core import Model
from acausal.errors import AnalysisError
from acausal.models.multibody import MultiBodyPendulum
from acausal.models.rolling import ROLLING_WHEEL_START, RollingWheelExample

CHROMIUM = "/usr/bin/chromium"
MAGENTA = (255, 0, 255)
FACETS = 1.1e-3     # [m] a sphere's mesh (16 around) stays within r·(1 − cos(π/16)) of it


@pytest.fixture(scope="module")
def pendulum():
    m = MultiBodyPendulum()
    res = acausal.compile(m).simulate(3.0, t=np.linspace(0, 3, 61))
    return m, res


def _camera(azimuth, elevation):
    """Screen right and screen up (world coordinates, rows) of the orthographic camera
    looking from ``azimuth`` / ``elevation`` [deg] about y up: at 0, 0 from +z with x to the
    right; the viewer at (cos el sin az, sin el, cos el cos az)."""
    az, el = np.radians(azimuth), np.radians(elevation)
    return np.array([[np.cos(az), 0.0, -np.sin(az)],
                     [-np.sin(el) * np.sin(az), np.cos(el), -np.sin(el) * np.cos(az)]])


def _pixels(points, lo, hi, camera, size=(480, 360)):
    """Pixels (column, row from the top-left) of world points [m] in a frame of ``size``
    that shows the box lo..hi (all parts over the whole motion) centred, its seen extent
    1.1 times the frame's smaller side (a 5 % margin each side)."""
    corners = np.array(list(itertools.product(*zip(lo, hi)))) @ camera.T
    centre = (corners.min(0) + corners.max(0)) / 2
    scale = min(size) / (1.1 * np.ptp(corners, axis=0).max())
    p = (np.atleast_2d(points) @ camera.T - centre) * scale
    return np.column_stack([size[0] / 2 + p[:, 0], size[1] / 2 - p[:, 1]])


def _sphere_box(centre, d):
    """Box (lo, hi) of spheres of diameter d [m] at the rows of ``centre``."""
    return centre - d / 2, centre + d / 2


def _rod_box(a, b, d):
    """Box (lo, hi) of cylinders of diameter d [m] from the rows of a to those of b: the rim
    reaches d/2·√(1 − u_i²) beyond the ends along axis i (u the unit axis)."""
    u = (b - a) / np.linalg.norm(b - a, axis=-1, keepdims=True)
    e = d / 2 * np.sqrt(np.clip(1 - u ** 2, 0, None))
    return np.minimum(a, b) - e, np.maximum(a, b) + e


def _box_of(boxes):
    """The box (lo, hi) holding every box in ``boxes`` at every instant."""
    return (np.min([np.min(np.atleast_2d(lo), 0) for lo, _ in boxes], 0),
            np.max([np.max(np.atleast_2d(hi), 0) for _, hi in boxes], 0))


def _mask(rgb, color, tol=60):
    return np.all(np.abs(rgb.astype(int) - np.array(color)) < tol, axis=-1)


def _magenta(rgb):
    """Pixels of magenta parts, at any shade."""
    r, g, b = (rgb[..., i].astype(int) for i in range(3))
    return (r > 80) & (b > 80) & (g < 40) & (np.abs(r - b) < 30)


def test_the_gif_frames_follow_the_pendulum_bob(pendulum, tmp_path):
    """The bob (MSL Body's sphere, diameter 1/9 m, at r_CM = 0.5 m along the body's x,
    turned by the revolute's angle phi about z) where the default 3-D view (azimuth 30°,
    elevation 20°) puts it; the view holds the revolute's cylinder (length 0.1 m, diameter
    0.05 m, along z), the body's rod (diameter 1/27 m) and the sphere over the motion."""
    m, res = pendulum
    shapes = shapes_of(m)
    for s in shapes:
        if s.kind == "sphere":
            s.color = MAGENTA                    # the bob, told apart from its rod
    anim = Animation(m, res, shapes=shapes)
    idx = anim.save_gif(tmp_path / "pendulum.gif", frames=12)
    gif = Image.open(tmp_path / "pendulum.gif")
    assert gif.n_frames == len(idx) == 12
    phi = res["rev.phi"]
    bob = 0.5 * np.column_stack([np.cos(phi), np.sin(phi), 0 * phi])
    pivot = np.zeros_like(bob)
    lo, hi = _box_of([_rod_box(np.array([0, 0, -0.05]), np.array([0, 0, 0.05]), 0.05),
                      _rod_box(pivot, bob, 1 / 27), _sphere_box(bob, 1 / 9)])
    np.testing.assert_allclose(np.vstack([anim.lo, anim.hi]), [lo, hi], atol=FACETS)
    expected = _pixels(bob, lo, hi, _camera(30.0, 20.0))
    seen = []
    for i, k in enumerate(idx):
        gif.seek(i)
        rows, cols = np.nonzero(_magenta(np.asarray(gif.convert("RGB"))))
        assert rows.size > 200                   # a sphere of 0.111 m is drawn
        assert np.hypot(cols.mean() - expected[k, 0], rows.mean() - expected[k, 1]) < 5, k
        seen.append(expected[k])
    seen = np.array(seen)
    assert np.ptp(seen[:, 0]) > 150              # the bob swings across the picture


def test_the_shapes_are_msl_s(pendulum):
    m = Model("box")
    m.world = World()
    m.box = BodyBox(r=(0.5, 0, 0), width=0.1, height=0.2, widthDirection=(0, 0, 1))
    (box,) = shapes_of(m)
    assert (box.kind, box.frame, box.length, box.width, box.height) == \
        ("box", "box.frame_a", 0.5, 0.1, 0.2)
    from acausal.analysis.animation import _mesh
    v, _ = _mesh(box)                            # along x, width along z, height along −y
    np.testing.assert_allclose(v.min(0), [0, -0.1, -0.05], atol=1e-12)
    np.testing.assert_allclose(v.max(0), [0.5, 0.1, 0.05], atol=1e-12)
    kinds = sorted(s.kind for s in shapes_of(pendulum[0]))
    assert kinds == ["cylinder", "cylinder", "sphere"]   # joint, Body's rod and sphere


def test_visualizers_are_drawn_where_msl_puts_them():
    """A FixedArrow and a FixedFrame on the swinging pendulum's body: the arrow's tip, from
    the animation's poses, is R_z(phi)·(r_tail + length·n/|n|) from the pivot (phi the
    revolute's angle); the frame's three axes are drawn in their colors."""
    from acausal.components.multibody.visualizers import FixedArrow, FixedFrame
    m = MultiBodyPendulum()
    m.arrow = FixedArrow(r_tail=(0.5, 0, 0), n=(0, 2, 0), length=0.3, color=(255, 0, 255))
    m.axes = FixedFrame(length=0.2, color_x=(255, 0, 0), color_y=(0, 255, 0),
                        color_z=(0, 0, 255))
    m.connect(m.body.frame_a, m.arrow.frame_a)
    m.connect(m.body.frame_a, m.axes.frame_a)
    res = acausal.compile(m).simulate(1.0, t=np.linspace(0, 1, 11))
    anim = Animation(m, res)
    k = next(i for i, s in enumerate(anim.shapes) if s.name == "arrow")
    tip = np.einsum("tij,j->ti", anim.poses[:, k], anim.shapes[k].local() @ [0.3, 0, 0, 1])
    phi = res["rev.phi"]
    hand = np.column_stack([0.5 * np.cos(phi) - 0.3 * np.sin(phi),
                            0.5 * np.sin(phi) + 0.3 * np.cos(phi), 0 * phi])
    np.testing.assert_allclose(tip[:, :3], hand, atol=1e-9)
    axes = [s for s in anim.shapes if s.name == "axes"]
    assert [s.color for s in axes] == [(255, 0, 0), (0, 255, 0), (0, 0, 255)]
    assert [s.lengthDirection for s in axes] == [(1, 0, 0), (0, 1, 0), (0, 0, 1)]


def test_the_html_is_self_contained(pendulum, tmp_path):
    m, res = pendulum
    Animation(m, res).save_html(tmp_path / "view.html")
    text = (tmp_path / "view.html").read_text()
    for outside in ("http:", "https:", "src=", "href=", "import "):
        assert outside not in text


def _screenshot(html, k, png):
    subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu",
                    "--disable-background-networking", "--disable-component-update",
                    "--no-first-run", "--window-size=640,480", f"--screenshot={png}",
                    f"file://{html}#frame={k}"], capture_output=True, timeout=180, check=True)
    return np.asarray(Image.open(png).convert("RGB"))[:400]       # above the control bar


@pytest.mark.skipif(not os.path.exists(CHROMIUM), reason=f"no headless browser ({CHROMIUM})")
def test_a_headless_browser_draws_the_parts(pendulum, tmp_path):
    m, res = pendulum
    shapes = shapes_of(m)
    for s in shapes:
        if s.kind == "sphere":
            s.color = MAGENTA
    html = tmp_path / "pendulum.html"
    Animation(m, res, shapes=shapes).save_html(html)
    bob, joint = [], []
    for k in (0, 10):
        view = _screenshot(html, k, tmp_path / f"p{k}.png")
        assert _magenta(view).sum() > 300                        # the Body's sphere
        assert _mask(view, (0, 110, 220), 60).sum() > 300       # its rod (shaded blue)
        red = (view[..., 0] > 120) & (view[..., 1] < 40) & (view[..., 2] < 40)
        assert red.sum() > 50                                    # the revolute joint
        bob.append(np.argwhere(_magenta(view)).mean(0))
        joint.append(np.argwhere(red).mean(0))
    # frame 0: the pendulum lies along +x, the bob right of the joint; frame 10 (t = 0.5 s)
    # it hangs below it
    assert bob[0][1] > joint[0][1] + 50
    assert bob[1][0] > joint[1][0] + 50
    np.testing.assert_allclose(joint[0], joint[1], atol=10)   # (the rod hides part of it)


@pytest.mark.skipif(not os.path.exists(CHROMIUM), reason=f"no headless browser ({CHROMIUM})")
def test_a_headless_browser_draws_the_rolling_wheel(tmp_path):
    m = RollingWheelExample()
    res = acausal.compile(m).simulate(1.0, x0=ROLLING_WHEEL_START, t=np.linspace(0, 1, 21))
    html = tmp_path / "wheel.html"
    Animation(m, res).save_html(html)
    view = _screenshot(html, 0, tmp_path / "wheel.png")
    dark = _mask(view, (30, 30, 30), 40)
    assert dark.sum() > 2000                                     # the wheel, a dark disc
    rows, cols = np.nonzero(dark)
    # an upright disc seen from −y turned by 30° about z: taller than wide by ~1/cos 30°
    assert 1.0 < np.ptp(rows) / np.ptp(cols) < 1.25


def test_bad_input_is_named(pendulum):
    m, res = pendulum
    with pytest.raises(AnalysisError, match="frame"):
        Animation(RollingWheelExample(), res)
    empty = Model("empty")
    empty.world = World()
    with pytest.raises(AnalysisError, match="no part to draw"):
        Animation(empty, res)


def test_planar_results_animate_seen_from_z(tmp_path):
    """Result.animate() of a planar double pendulum: PlanarMechanics' shapes, the GIF's
    bob where the view from +z puts body2 (from the joint angles: each bar r = (0, −0.5) m
    turned by the angles before it); the view holds the revolutes (cylinders along z of
    length and diameter 0.1 m), the bars (diameter 0.5/20 m) and the bodies (spheres of
    diameter 1/9 m) over the motion."""
    from acausal.models.pendulums import PendulumChain
    res = acausal.compile(PendulumChain(2)).simulate(2.0, t=np.linspace(0, 2, 41),
                                                      x0={"rev1.phi": 1.0})
    a1, a2 = res["rev1.phi"], res["rev1.phi"] + res["rev2.phi"]
    body1 = 0.5 * np.column_stack([np.sin(a1), -np.cos(a1), 0 * a1])
    body2 = body1 + 0.5 * np.column_stack([np.sin(a2), -np.cos(a2), 0 * a2])
    pivot, dz = np.zeros_like(body1), np.array([0, 0, 0.05])
    lo, hi = _box_of([_rod_box(pivot - dz, pivot + dz, 0.1),
                      _rod_box(body1 - dz, body1 + dz, 0.1),
                      _rod_box(pivot, body1, 0.025), _rod_box(body1, body2, 0.025),
                      _sphere_box(body1, 1 / 9), _sphere_box(body2, 1 / 9)])
    expected = _pixels(body2, lo, hi, _camera(0.0, 0.0))
    anim = res.animate()
    assert anim.planar and (anim.azimuth, anim.elevation) == (0.0, 0.0)
    assert [(s.name, s.kind) for s in anim.shapes] == [
        ("rev1", "cylinder"), ("bar1", "cylinder"), ("body1", "sphere"),
        ("rev2", "cylinder"), ("bar2", "cylinder"), ("body2", "sphere")]
    for s in anim.shapes:
        if s.name == "body2":
            s.color = MAGENTA
    anim = res.animate(shapes=anim.shapes)
    idx = anim.save(tmp_path / "double.gif", frames=8)
    gif = Image.open(tmp_path / "double.gif")
    np.testing.assert_allclose(np.vstack([anim.lo, anim.hi]), [lo, hi], atol=FACETS)
    for i, k in enumerate(idx):
        gif.seek(i)
        rows, cols = np.nonzero(_magenta(np.asarray(gif.convert("RGB"))))
        assert rows.size > 100 and np.hypot(cols.mean() - expected[k, 0],
                                            rows.mean() - expected[k, 1]) < 3, k
    page = anim._repr_html_()
    assert page.startswith("<iframe") and "&quot;poses&quot;" in page
    with pytest.raises(AnalysisError, match=".html, .gif or .mp4"):
        anim.save(tmp_path / "double.png")


def test_a_prismatic_is_drawn_as_long_as_its_stroke():
    """PlanarMechanics' Prismatic box runs from frame_a along r for the length s."""
    from acausal.models import CartPole
    res = acausal.compile(CartPole()).simulate(1.0, t=np.linspace(0, 1, 11),
                                               inputs={"F": 5.0})
    anim = res.animate()
    (k,) = [i for i, s in enumerate(anim.shapes) if s.name == "rail"]
    v = anim.meshes[k][0]
    for j in range(len(anim.t)):
        P = anim.poses[j, k]
        world = v @ P[:3, :3].T + P[:3, 3]
        start, s = res["rail.frame_a.x"][j], res["rail.s"][j]
        np.testing.assert_allclose([world[:, 0].min(), world[:, 0].max()],
                                   sorted([start, start + s]), atol=1e-12)
    assert res["rail.s"][-1] > 0.5              # pushed along the rail


def test_mp4_without_ffmpeg_says_what_to_do(pendulum, tmp_path, monkeypatch):
    from matplotlib.animation import writers
    monkeypatch.setattr(writers, "is_available", lambda name: False)
    m, res = pendulum
    with pytest.raises(AnalysisError, match="needs ffmpeg on the PATH.*save a .gif or .html"):
        Animation(m, res).save(tmp_path / "run.mp4")
    assert not (tmp_path / "run.mp4").exists()
