"""Animation of multibody results, 3-D and planar: the parts drawn from their shapes as MSL
and PlanarMechanics draw them, in an interactive view in the browser (a self-contained HTML
file, also what a notebook shows) and as a GIF or MP4 (``Result.animate()``).

Shapes follow MSL's Visualizers.Advanced.Shape: a primitive (box, cylinder, sphere) placed in
a frame of a part by r_shape [m], lengthDirection and widthDirection (resolved in the frame),
length, width, height [m] and a colour (RGB 0..255). The parts draw what MSL draws by
default (world.nominalLength = 1 m):

- Body: a cylinder from frame_a to the centre of mass (diameter 0.111/3 m) and a sphere at
  the centre of mass (diameter 0.111 m, world.defaultBodyDiameter);
- BodyShape: a cylinder from r_shape along lengthDirection (width length/20) and the sphere;
  BodyBox a box, BodyCylinder a cylinder of its own dimensions;
- FixedTranslation: a cylinder from frame_a to frame_b (width length/20);
- Revolute: a cylinder along its axis (length 0.1 m, diameter 0.05 m); Prismatic: a box
  along its axis from frame_a to frame_b;
- RollingWheel, RollingWheelSet: the wheels as discs (width, radius); PointMass: a sphere.

Planar parts (``acausal.components.planar``) draw what PlanarMechanics draws, in the plane
z = 0 (planarWorld.nominalLength = 1 m): Body a sphere at frame_a (diameter 1/9 m),
FixedTranslation a cylinder along r (width |r|/20), Revolute a cylinder along z (length and
diameter 0.1 m), Prismatic a box from frame_a along r of length s (width |r|/20).

Other part classes draw nothing unless a drawing function is registered for them
(``register``). A shape's pose at each instant comes from its frame's recorded r_0 and R.T
in the Result (every frame records them; a planar frame its x, y, phi); a shape whose length
follows a variable (``length_variable``: a Prismatic's s) is stretched along its length
direction at each instant. The world's up direction is against its gravity (``World.n``); a
planar model is seen from +z.

Rendering is this module's own: triangle meshes, orthographic projection and flat shading
sorted back to front (painter's algorithm). The HTML view repeats it in a small script
drawing on a 2-D canvas (no WebGL, nothing loaded from outside the file): drag to turn,
wheel to zoom, a slider and play button for time. The GIF is drawn with matplotlib
(PolyCollection) and written by Pillow, with the same camera; ``Animation.project`` maps
world points to its pixels (what the tests check the frames against).
"""
from __future__ import annotations

import json
from dataclasses import dataclass, field
from html import escape

import numpy as np

from ..errors import AnalysisError

__all__ = ["Shape", "Animation", "register", "shapes_of"]


@dataclass
class Shape:
    """A primitive drawn in the frame ``frame`` (a port's dotted path): ``kind`` "box",
    "cylinder" (along lengthDirection, diameter width, height) or "sphere" (diameter
    length, starting at r_shape as in MSL); dimensions [m]; ``color`` RGB 0..255;
    ``length_variable``: the name of a variable [m] that is the length at each instant
    (``length`` is then the length the mesh is built with)."""
    frame: str
    kind: str
    length: float
    width: float
    height: float
    r_shape: tuple = (0.0, 0.0, 0.0)
    lengthDirection: tuple = (1.0, 0.0, 0.0)
    widthDirection: tuple = (0.0, 1.0, 0.0)
    color: tuple = (0, 128, 255)
    name: str = field(default="")
    length_variable: str = ""       # a variable whose value is the length at each instant

    def local(self) -> np.ndarray:
        """4×4 pose of the primitive in its frame (x along lengthDirection)."""
        ex = np.asarray(self.lengthDirection, float)
        ex = ex / np.linalg.norm(ex)
        wy = np.asarray(self.widthDirection, float)
        ey = wy - ex * (ex @ wy)
        if np.linalg.norm(ey) < 1e-9:                 # parallel: another axis, as MSL
            ey = np.cross(ex, [0.0, 0.0, 1.0] if abs(ex[2]) < 0.9 else [1.0, 0.0, 0.0])
        ey = ey / np.linalg.norm(ey)
        M = np.eye(4)
        M[:3, :3] = np.column_stack([ex, ey, np.cross(ex, ey)])
        M[:3, 3] = self.r_shape
        return M


# ---- meshes of unit primitives, in the primitive's own axes -------------------------------
def _box():
    v = np.array([[x, y, z] for x in (0, 1) for y in (-.5, .5) for z in (-.5, .5)], float)
    q = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    return v, np.array([t for a, b, c, d in q for t in ((a, b, c), (a, c, d))])


def _cylinder(n=24):
    a = np.linspace(0, 2 * np.pi, n, endpoint=False)
    ring = np.column_stack([np.zeros(n), 0.5 * np.cos(a), 0.5 * np.sin(a)])
    v = np.vstack([ring, ring + [1, 0, 0], [[0, 0, 0], [1, 0, 0]]])
    tris = []
    for i in range(n):
        j = (i + 1) % n
        tris += [(i, j, n + j), (i, n + j, n + i), (2 * n, j, i), (2 * n + 1, n + i, n + j)]
    return v, np.array(tris)


def _sphere(n=16):
    th, ph = np.linspace(0, np.pi, n // 2 + 1), np.linspace(0, 2 * np.pi, n, endpoint=False)
    v = np.array([[0.5 - 0.5 * np.cos(t), 0.5 * np.sin(t) * np.cos(p), 0.5 * np.sin(t) * np.sin(p)]
                  for t in th for p in ph])
    tris = []
    for i in range(len(th) - 1):
        for k in range(n):
            a, b = i * n + k, i * n + (k + 1) % n
            tris += [(a, b, b + n), (a, b + n, a + n)]
    return v, np.array(tris)


_MESHES = {"box": _box(), "cylinder": _cylinder(), "sphere": _sphere()}


def _mesh(shape: Shape) -> tuple[np.ndarray, np.ndarray]:
    """Vertices (in the shape's frame) and triangles of a shape."""
    v, tris = _MESHES[shape.kind]
    scale = (shape.length, shape.length, shape.length) if shape.kind == "sphere" else \
        (shape.length, shape.width, shape.height)
    v = v * scale
    M = shape.local()
    return v @ M[:3, :3].T + M[:3, 3], tris


# ---- what each part draws (MSL's defaults) ------------------------------------------------
_DRAW: dict = {}


def register(cls: type, draw) -> None:
    """Draw the parts of class ``cls`` (and its subclasses) with ``draw(component) -> list
    of Shape``."""
    _DRAW[cls] = draw


def _val(c, name):
    v = getattr(c, name)
    return tuple(float(x) for x in v) if isinstance(v, (tuple, list)) else float(v)


def _path(c, port):
    return f"{c.path}.{port}" if c.path else port


_BODY_D = 1.0 / 9            # world.defaultBodyDiameter (nominalLength 1 m)
_WIDTH_FRACTION = 20.0       # world.defaultWidthFraction


def _body_sphere(c) -> Shape:
    r = np.asarray(_val(c, "r_CM"))
    return Shape(_path(c, "frame_a"), "sphere", _BODY_D, _BODY_D, _BODY_D,
                 tuple(r - np.array([_BODY_D / 2, 0, 0])), color=(0, 128, 255), name=c.path)


def _body(c):
    out = [_body_sphere(c)]
    r = np.asarray(_val(c, "r_CM"))
    if np.linalg.norm(r) > 1e-12:
        out.append(Shape(_path(c, "frame_a"), "cylinder", float(np.linalg.norm(r)),
                         _BODY_D / 3, _BODY_D / 3, lengthDirection=tuple(r),
                         color=(0, 128, 255), name=c.path))
    return out


def _body_shape(c):
    L = float(np.linalg.norm(_val(c, "r")))
    return [Shape(_path(c, "frame_a"), "cylinder", L, L / _WIDTH_FRACTION, L / _WIDTH_FRACTION,
                  lengthDirection=_val(c, "r") if L > 0 else (1, 0, 0), color=(0, 128, 255),
                  name=c.path), _body_sphere(c)]


def _shaped(kind):
    def draw(c):
        if kind == "box":
            w, h = _val(c, "width"), _val(c, "height")
            wd = _val(c, "widthDirection")
        else:
            w = h = _val(c, "diameter")
            wd = (0.0, 1.0, 0.0)
        return [Shape(_path(c, "frame_a"), kind, _val(c, "length"), w, h, _val(c, "r_shape"),
                      _val(c, "lengthDirection"), wd, (0, 128, 255), c.path)]
    return draw


def _translation(c):
    r = _val(c, "r")
    r = (*r, 0.0) if len(r) == 2 else r          # a planar one, in the plane z = 0
    L = float(np.linalg.norm(r))
    if L == 0:
        return []
    return [Shape(_path(c, "frame_a"), "cylinder", L, L / _WIDTH_FRACTION, L / _WIDTH_FRACTION,
                  lengthDirection=r, color=(155, 155, 155), name=c.path)]


def _revolute(c):
    n = np.asarray(_val(c, "n"))
    return [Shape(_path(c, "frame_a"), "cylinder", 0.1, 0.05, 0.05, tuple(-0.05 * n / np.linalg.norm(n)),
                  tuple(n), color=(255, 0, 0), name=c.path)]


def _wheel(radius, width, frame, name):
    return Shape(frame, "cylinder", 2 * width, 2 * radius, 2 * radius, (0.0, -width, 0.0),
                 (0.0, 1.0, 0.0), (1.0, 0.0, 0.0), (30, 30, 30), name)


def _point_mass(c):
    return [Shape(_path(c, "frame_a"), "sphere", _BODY_D, _BODY_D, _BODY_D,
                  (-_BODY_D / 2, 0.0, 0.0), color=(0, 128, 255), name=c.path)]


def _rgb(color) -> tuple:
    return tuple(int(round(x)) for x in color)


_KIND = {"box": "box", "beam": "box", "sphere": "sphere", "cylinder": "cylinder",
         "cone": "cylinder", "pipe": "cylinder", "gearwheel": "cylinder", "spring": "cylinder"}


def _fixed_shape(c):
    """Visualizers.FixedShape: MSL's primitive (cones, pipes, gear wheels and springs as
    cylinders, other shapes as boxes)."""
    d = c.shape()
    return [Shape(_path(c, "frame_a"), _KIND.get(d["shapeType"], "box"), d["length"],
                  d["width"], d["height"], d["r_shape"], d["lengthDirection"],
                  d["widthDirection"], _rgb(d["color"]), c.path)]


def _fixed_frame(c):
    """Visualizers.FixedFrame: its three axes as rods of ``length``."""
    d = c.shape()
    return [Shape(_path(c, "frame_a"), "cylinder", d["length"], d["diameter"], d["diameter"],
                  (0.0, 0.0, 0.0), axis, color=_rgb(d[f"color_{x}"]), name=c.path)
            for x, axis in (("x", (1.0, 0, 0)), ("y", (0, 1.0, 0)), ("z", (0, 0, 1.0)))]


def _fixed_arrow(c):
    """Visualizers.FixedArrow: a rod of ``length`` from r_tail along n."""
    d = c.shape()
    return [Shape(_path(c, "frame_a"), "cylinder", d["length"], d["diameter"], d["diameter"],
                  d["r_tail"], d["n"], color=_rgb(d["color"]), name=c.path)]


# ---- planar parts (PlanarMechanics' defaults, in the plane z = 0) ------------------------
_JOINT = 0.1                 # planarWorld.defaultJointLength = defaultJointWidth [m]


def _planar_revolute(c):
    return [Shape(_path(c, "frame_a"), "cylinder", _JOINT, _JOINT, _JOINT,
                  (0.0, 0.0, -_JOINT / 2), (0.0, 0.0, 1.0), (1.0, 0.0, 0.0), (255, 0, 0),
                  c.path)]


def _planar_prismatic(c):
    r = (*_val(c, "r"), 0.0)
    w = float(np.linalg.norm(r)) / _WIDTH_FRACTION
    return [Shape(_path(c, "frame_a"), "box", 1.0, w, w, lengthDirection=r,
                  widthDirection=(0.0, 0.0, 1.0), color=(255, 0, 0), name=c.path,
                  length_variable=f"{c.path}.s" if c.path else "s")]


def _defaults():
    from ..components import planar
    from ..components.multibody import (Body, BodyBox, BodyCylinder, BodyShape,
                                        FixedTranslation, PointMass, Revolute, RollingWheel,
                                        RollingWheelSet)
    from ..components.multibody.visualizers import FixedArrow, FixedFrame, FixedShape
    register(FixedShape, _fixed_shape)
    register(FixedFrame, _fixed_frame)
    register(FixedArrow, _fixed_arrow)
    register(Body, _body)
    register(BodyShape, _body_shape)
    register(BodyBox, _shaped("box"))
    register(BodyCylinder, _shaped("cylinder"))
    register(FixedTranslation, _translation)
    register(Revolute, _revolute)
    register(PointMass, _point_mass)
    register(RollingWheel, lambda c: [_wheel(_val(c, "radius"), _val(c, "width"),
                                              _path(c, "frame_a"), c.path)])
    register(planar.Body, _point_mass)      # a sphere at frame_a
    register(planar.FixedTranslation, _translation)
    register(planar.Revolute, _planar_revolute)
    register(planar.Prismatic, _planar_prismatic)
    register(RollingWheelSet, lambda c: [
        _wheel(_val(c, "R_wheel"), _val(c, "width_wheel"), _path(c, f), c.path)
        for f in ("frame1", "frame2")])


def _walk(c):
    yield c
    for child in c.children.values():
        yield from _walk(child)


def shapes_of(model) -> list[Shape]:
    """The shapes of the parts of ``model`` (a Model) that are animated (``animation``
    True, the default)."""
    if not _DRAW:
        _defaults()
    out = []
    for c in _walk(model):
        if not getattr(c, "animation", True):
            continue
        for cls in type(c).__mro__:
            if cls in _DRAW:
                out += _DRAW[cls](c)
                break
    return out


def _up(model) -> np.ndarray:
    """The world's up direction: against World.n (a planar World's n in the plane z = 0;
    default y up)."""
    from ..components import planar
    from ..components.multibody import World
    for c in _walk(model):
        if isinstance(c, (World, planar.World)):
            n = np.asarray(_val(c, "n"))
            n = np.append(n, 0.0) if n.size == 2 else n
            return -n / np.linalg.norm(n)
    return np.array([0.0, 1.0, 0.0])


class Animation:
    """The parts of ``model`` (a Model, or a CompiledModel compiled from one) moving as in
    ``result``; ``shapes`` replaces the parts' own (a list of Shape). Camera: orthographic,
    looking from ``azimuth`` / ``elevation`` [deg] about the world's up direction (0, 0:
    from +z with x to the right when y is up, from −y when z is up, MSL's default views;
    default 30, 20 for a 3-D model, 0, 0 for a planar one). In a notebook the interactive
    view shows itself; ``save`` writes it (.html), a GIF or an MP4."""

    def __init__(self, model, result, shapes: list[Shape] | None = None,
                 azimuth: float | None = None, elevation: float | None = None):
        model = getattr(model, "source", None) or model
        self.shapes = shapes_of(model) if shapes is None else list(shapes)
        if not self.shapes:
            raise AnalysisError(f"model '{model.name}' has no part to draw (no Body, BodyShape, "
                                f"BodyBox, BodyCylinder, FixedTranslation, wheel, planar Body "
                                f"...)")
        self.t = np.asarray(result.t, float)
        self.up = _up(model)
        self.meshes = [_mesh(s) for s in self.shapes]
        poses = [self._frame_poses(result, s.frame) for s in self.shapes]
        self.planar = all(planar for _, planar in poses)
        view = (0.0, 0.0) if self.planar else (30.0, 20.0)
        self.azimuth = float(view[0] if azimuth is None else azimuth)
        self.elevation = float(view[1] if elevation is None else elevation)
        self.poses = np.stack([P @ self._stretch(result, s) for (P, _), s in
                               zip(poses, self.shapes)], 1)
        pts = np.concatenate([np.einsum("tij,vj->tvi", P[:, :3, :3], v).reshape(-1, 3)
                              + np.repeat(P[:, :3, 3], len(v), 0)
                              for P, (v, _) in zip(self.poses.transpose(1, 0, 2, 3),
                                                   self.meshes)])
        self.lo, self.hi = pts.min(0), pts.max(0)

    @staticmethod
    def _frame_poses(result, frame: str) -> tuple[np.ndarray, bool]:
        """4×4 poses (world from frame) of ``frame`` at every instant of ``result``, and
        whether it is a planar frame (x, y, phi in the plane z = 0)."""
        try:
            if f"{frame}.x" in result:
                x, y, phi = (result[f"{frame}.{v}"] for v in ("x", "y", "phi"))
                P = np.zeros((len(x), 4, 4))
                P[:, 0, 0], P[:, 0, 1], P[:, 0, 3] = np.cos(phi), -np.sin(phi), x
                P[:, 1, 0], P[:, 1, 1], P[:, 1, 3] = np.sin(phi), np.cos(phi), y
                P[:, 2, 2] = P[:, 3, 3] = 1
                return P, True
            r = np.column_stack([result[f"{frame}.r_0[{k}]"] for k in (1, 2, 3)])
            T = np.stack([[result[f"{frame}.R.T[{i},{j}]"] for j in (1, 2, 3)]
                          for i in (1, 2, 3)])
        except KeyError as e:
            raise AnalysisError(f"the result does not record frame '{frame}' ({e}); animate "
                                f"the result of the model the shapes belong to") from None
        P = np.zeros((len(r), 4, 4))
        P[:, :3, :3] = np.transpose(T, (2, 1, 0))      # world from frame = Tᵀ
        P[:, :3, 3] = r
        P[:, 3, 3] = 1
        return P, False

    @staticmethod
    def _stretch(result, shape: Shape) -> np.ndarray:
        """Per instant, the affine map (in the shape's frame) that gives a shape with a
        ``length_variable`` that length: a scaling along its length direction from
        r_shape; the identity for the others."""
        if not shape.length_variable:
            return np.eye(4)
        M = shape.local()
        k = np.asarray(result[shape.length_variable], float) / shape.length
        D = np.tile(np.eye(4), (len(k), 1, 1))
        D[:, 0, 0] = k
        return M @ D @ np.linalg.inv(M)

    def camera(self) -> np.ndarray:
        """3×3 rows: screen right, screen up, towards the viewer (world coordinates)."""
        up = self.up
        ref = np.array([1.0, 0, 0]) if abs(up[0]) < 0.9 else np.array([0, 0, 1.0])
        e1 = ref - up * (up @ ref)
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(e1, up)
        az, el = np.radians(self.azimuth), np.radians(self.elevation)
        back = np.cos(el) * (np.cos(az) * e2 + np.sin(az) * e1) + np.sin(el) * up
        right = np.cross(up, back)
        right /= np.linalg.norm(right)
        return np.vstack([right, np.cross(back, right), back])

    def _view_box(self):
        C = self.camera()
        corners = np.array([[x, y, z] for x in (self.lo[0], self.hi[0])
                            for y in (self.lo[1], self.hi[1]) for z in (self.lo[2], self.hi[2])])
        p = corners @ C[:2].T
        lo, hi = p.min(0), p.max(0)
        c, half = (lo + hi) / 2, 0.55 * max(hi - lo) + 1e-9
        return c, half

    def project(self, points, size=(480, 360)) -> np.ndarray:
        """Pixel coordinates (column, row from the top-left) of world points [m] in the
        GIF's frames of ``size`` (width, height)."""
        C = self.camera()
        c, half = self._view_box()
        W, H = size
        s = min(W, H) / (2 * half)
        p = (np.atleast_2d(points) @ C[:2].T - c) * s
        return np.column_stack([W / 2 + p[:, 0], H / 2 - p[:, 1]])

    def _triangles(self, k: int):
        """World triangles of instant k, with their colours (RGB 0..1, flat shaded), back
        to front."""
        C = self.camera()
        polys, cols, depth = [], [], []
        for (v, tris), P, s in zip(self.meshes, self.poses[k], self.shapes):
            w = v @ P[:3, :3].T + P[:3, 3]
            tri = w[tris]
            n = np.cross(tri[:, 1] - tri[:, 0], tri[:, 2] - tri[:, 0])
            n /= np.linalg.norm(n, axis=1, keepdims=True) + 1e-300
            shade = 0.35 + 0.65 * np.abs(n @ C[2])
            polys.append(tri)
            cols.append(np.clip(np.outer(shade, np.asarray(s.color) / 255), 0, 1))
            depth.append(tri.mean(1) @ C[2])
        polys, cols, depth = np.concatenate(polys), np.concatenate(cols), np.concatenate(depth)
        order = np.argsort(depth)
        return polys[order], cols[order]

    def save(self, path, **kwargs):
        """Write the animation to ``path`` by its suffix: .html (``save_html``), .gif
        (``save_gif``) or .mp4 (``save_mp4``)."""
        kind = str(path).rsplit(".", 1)[-1].lower()
        writers = {"html": self.save_html, "gif": self.save_gif, "mp4": self.save_mp4}
        if kind not in writers:
            raise AnalysisError(f"cannot save an animation as '.{kind}' ({path}); give a path "
                                f"ending in .html, .gif or .mp4")
        return writers[kind](path, **kwargs)

    def save_gif(self, path, fps: float = 15, size=(480, 360), frames: int | None = None):
        """Write the animation as a GIF (matplotlib, Pillow writer), ``frames`` instants
        evenly spread over the result (default all); returns the indices of the instants
        drawn."""
        from matplotlib.animation import PillowWriter
        return self._write(path, PillowWriter(fps=fps), size, frames)

    def save_mp4(self, path, fps: float = 15, size=(480, 360), frames: int | None = None):
        """Write the animation as an MP4 video (matplotlib's ffmpeg writer: needs ffmpeg on
        the PATH); as ``save_gif`` otherwise."""
        from matplotlib.animation import FFMpegWriter, writers
        if not writers.is_available("ffmpeg"):
            raise AnalysisError(f"saving '{path}' as MP4 needs ffmpeg on the PATH (not found); "
                                f"install ffmpeg, or save a .gif or .html")
        return self._write(path, FFMpegWriter(fps=fps), size, frames)

    def _write(self, path, writer, size, frames):
        """Draw the frames with matplotlib and hand them to ``writer``."""
        from matplotlib.animation import FuncAnimation
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.collections import PolyCollection
        from matplotlib.figure import Figure
        W, H = size
        dpi = 100
        fig = Figure(figsize=(W / dpi, H / dpi), dpi=dpi)       # no pyplot, any backend
        FigureCanvasAgg(fig)
        ax = fig.add_axes((0, 0, 1, 1))
        ax.set_xlim(0, W)
        ax.set_ylim(H, 0)
        ax.axis("off")
        coll = PolyCollection([], edgecolors="face", linewidths=0.3)
        ax.add_collection(coll)
        label = ax.text(8, 18, "", fontsize=9)
        idx = self._instants(frames)

        def draw(i):
            k = idx[i]
            tri, col = self._triangles(k)
            px = self.project(tri.reshape(-1, 3), size).reshape(-1, 3, 2)
            coll.set_verts(px)
            coll.set_facecolor(col)
            label.set_text(f"t = {self.t[k]:.2f} s")
            return coll, label

        anim = FuncAnimation(fig, draw, frames=len(idx), blit=False)
        anim.save(str(path), writer=writer, dpi=dpi)
        return idx

    def save_html(self, path, title: str = "acausal animation", frames: int | None = None):
        """Write a self-contained HTML file (no external resources) with the interactive
        view: drag to turn, wheel to zoom, slider and play button for time (``#frame=k``
        after the file's address opens it paused at the k-th instant drawn)."""
        with open(path, "w", encoding="utf-8") as f:
            f.write(self.html(title, frames))

    def html(self, title: str = "acausal animation", frames: int | None = None) -> str:
        """The self-contained HTML page of the interactive view (``save_html``)."""
        idx = self._instants(frames)
        data = {
            "t": [round(float(x), 6) for x in self.t[idx]],
            "up": self.up.tolist(), "azimuth": self.azimuth, "elevation": self.elevation,
            "lo": self.lo.tolist(), "hi": self.hi.tolist(),
            "shapes": [{"v": np.round(v, 6).ravel().tolist(), "f": tris.ravel().tolist(),
                        "c": list(s.color), "name": s.name} for (v, tris), s in
                       zip(self.meshes, self.shapes)],
            "poses": np.round(self.poses[idx][:, :, :3, :].reshape(len(idx), -1), 7).tolist(),
        }
        return _HTML.replace("__TITLE__", title).replace("__DATA__", json.dumps(data))

    def _instants(self, frames: int | None) -> np.ndarray:
        """Indices of ``frames`` instants evenly spread over the result (default all)."""
        return np.arange(len(self.t)) if frames is None else \
            np.unique(np.linspace(0, len(self.t) - 1, frames).round().astype(int))

    def _repr_html_(self) -> str:
        """The interactive view in a notebook (the page in an iframe, at most 200
        instants)."""
        page = self.html(frames=min(len(self.t), 200))
        return ('<iframe style="width:100%;height:420px;border:0" srcdoc="'
                + escape(page, quote=True) + '"></iframe>')


_HTML = r"""<!DOCTYPE html>
<html><head><meta charset="utf-8"><title>__TITLE__</title>
<style>body{margin:0;background:#f4f4f4;font-family:sans-serif}
#bar{position:fixed;bottom:0;left:0;right:0;padding:6px;background:#ddd}
#time{width:60%}canvas{display:block}</style></head>
<body><canvas id="view"></canvas>
<div id="bar"><button id="play">pause</button> <input id="time" type="range" min="0" value="0">
<span id="label"></span></div>
<script>
const D = __DATA__;
const cv = document.getElementById("view"), g = cv.getContext("2d");
const slider = document.getElementById("time"), label = document.getElementById("label");
const playBtn = document.getElementById("play");
slider.max = D.t.length - 1;
let az = D.azimuth * Math.PI / 180, el = D.elevation * Math.PI / 180, zoom = 1;
let frame = 0, playing = true, last = null;
const sub = (a, b) => [a[0]-b[0], a[1]-b[1], a[2]-b[2]];
const dot = (a, b) => a[0]*b[0] + a[1]*b[1] + a[2]*b[2];
const cross = (a, b) => [a[1]*b[2]-a[2]*b[1], a[2]*b[0]-a[0]*b[2], a[0]*b[1]-a[1]*b[0]];
const scale = (a, s) => [a[0]*s, a[1]*s, a[2]*s];
const norm = a => scale(a, 1 / Math.hypot(a[0], a[1], a[2]));
function camera() {
  const up = D.up;
  const ref = Math.abs(up[0]) < 0.9 ? [1, 0, 0] : [0, 0, 1];
  const e1 = norm(sub(ref, scale(up, dot(up, ref)))), e2 = cross(e1, up);
  const back = [0, 1, 2].map(i => Math.cos(el) * (Math.cos(az) * e2[i] + Math.sin(az) * e1[i])
                                  + Math.sin(el) * up[i]);
  const right = norm(cross(up, back));
  return [right, cross(back, right), back];
}
function draw() {
  const W = cv.width = window.innerWidth, H = cv.height = window.innerHeight - 40;
  g.fillStyle = "#f4f4f4"; g.fillRect(0, 0, W, H);
  const C = camera();
  const mid = [0, 1, 2].map(i => (D.lo[i] + D.hi[i]) / 2);
  const ext = Math.hypot(D.hi[0]-D.lo[0], D.hi[1]-D.lo[1], D.hi[2]-D.lo[2]) / 2 + 1e-9;
  const s = zoom * Math.min(W, H) / (2.2 * ext);
  const P = D.poses[frame], tris = [];
  D.shapes.forEach((sh, k) => {
    const m = P.slice(12 * k, 12 * k + 12), n = sh.v.length / 3, w = [];
    for (let i = 0; i < n; i++) {
      const x = sh.v[3*i], y = sh.v[3*i+1], z = sh.v[3*i+2];
      w.push([m[0]*x + m[1]*y + m[2]*z + m[3], m[4]*x + m[5]*y + m[6]*z + m[7],
              m[8]*x + m[9]*y + m[10]*z + m[11]]);
    }
    for (let f = 0; f < sh.f.length; f += 3) {
      const a = w[sh.f[f]], b = w[sh.f[f+1]], c = w[sh.f[f+2]];
      const nn = cross(sub(b, a), sub(c, a)), len = Math.hypot(nn[0], nn[1], nn[2]) || 1;
      const shade = 0.35 + 0.65 * Math.abs(dot(nn, C[2]) / len);
      const depth = (dot(a, C[2]) + dot(b, C[2]) + dot(c, C[2])) / 3;
      tris.push([depth, [a, b, c], sh.c.map(v => Math.round(v * shade))]);
    }
  });
  tris.sort((p, q) => p[0] - q[0]);
  for (const [, pts, col] of tris) {
    g.beginPath();
    pts.forEach((p, i) => {
      const d = sub(p, mid), X = W / 2 + s * dot(d, C[0]), Y = H / 2 - s * dot(d, C[1]);
      i ? g.lineTo(X, Y) : g.moveTo(X, Y);
    });
    g.closePath();
    g.fillStyle = g.strokeStyle = `rgb(${col[0]},${col[1]},${col[2]})`;
    g.fill(); g.stroke();
  }
  slider.value = frame;
  label.textContent = `t = ${D.t[frame].toFixed(2)} s`;
}
function tick(ts) {
  if (playing) {
    if (last === null) last = ts;
    const t0 = D.t[0], span = D.t[D.t.length - 1] - t0;
    const now = t0 + ((ts - last) / 1000) % (span || 1);
    let k = 0; while (k < D.t.length - 1 && D.t[k + 1] <= now) k++;
    frame = k;
  }
  draw(); requestAnimationFrame(tick);
}
let drag = null;
cv.onmousedown = e => drag = [e.clientX, e.clientY];
window.onmouseup = () => drag = null;
window.onmousemove = e => {
  if (!drag) return;
  az -= (e.clientX - drag[0]) * 0.01;
  el = Math.max(-1.5, Math.min(1.5, el + (e.clientY - drag[1]) * 0.01));
  drag = [e.clientX, e.clientY];
};
cv.onwheel = e => { zoom *= Math.exp(-e.deltaY * 0.001); e.preventDefault(); };
slider.oninput = () => { playing = false; playBtn.textContent = "play"; frame = +slider.value; };
playBtn.onclick = () => { playing = !playing; last = null;
  playBtn.textContent = playing ? "pause" : "play"; };
const fixed = /^#frame=(\d+)$/.exec(location.hash);   // e.g. view.html#frame=10: paused there
if (fixed) { frame = Math.min(+fixed[1], D.t.length - 1); playing = false;
  playBtn.textContent = "play"; }
draw();
requestAnimationFrame(tick);
</script></body></html>
"""
