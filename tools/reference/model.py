"""Reads a problem file (format version 1) into plain Python objects.

Constant-only quantities (masses, inertias, centers, joint placements, axes, points) are
evaluated to numbers here; load expressions are kept as trees and evaluated at each state.
The checks here are only those the reference needs to compute; `mbd-tutor check` is the
validator.
"""

import json
import math
import sys

import expr as ex
from linalg import norm, vscale

JOINT_DOF = {"revolute": 1, "prismatic": 1, "cylindrical": 2, "planar": 3,
             "universal": 2, "spherical": 3, "free": 6, "weld": 0}
# Which coordinates of each joint type translate (T) and which rotate (R), in order.
JOINT_KINDS = {"revolute": "R", "prismatic": "T", "cylindrical": "TR", "planar": "TTR",
               "universal": "RR", "spherical": "RRR", "free": "TTTRRR", "weld": ""}
LOAD_KEYS = {
    "force": ({"on", "vector"}, {"at"}),
    "torque": ({"on", "vector"}, {"reaction_on"}),
    "spring": ({"between", "stiffness"}, {"free_length"}),
    "damper": ({"between", "coefficient"}, set()),
    "joint_spring": ({"joint", "coordinate", "stiffness"}, {"rest"}),
    "joint_damper": ({"joint", "coordinate", "coefficient"}, set()),
    "joint_actuator": ({"joint", "coordinate", "value"}, set()),
}


class ProblemError(Exception):
    """The problem cannot be read; the message starts with the JSON path."""


def _keys(obj, path, required, optional):
    if not isinstance(obj, dict):
        raise ProblemError(f"{path}: expected an object")
    for k in obj:
        if k not in required and k not in optional:
            raise ProblemError(f"{path}.{k}: unknown key")
    for k in required:
        if k not in obj:
            raise ProblemError(f"{path}: missing key {k!r}")


class Body:
    def __init__(self, name):
        self.name = name
        self.mass = 0.0
        self.center = [0.0, 0.0, 0.0]
        self.inertia = [[0.0] * 3 for _ in range(3)]  # central, in body axes


class Joint:
    def __init__(self, name, jtype, parent, child):
        self.name, self.type, self.parent, self.child = name, jtype, parent, child
        self.coords = []          # indices into Problem.coords
        self.axis = None          # unit axis in parent components
        self.sequence = []        # 0 1 2 for x y z
        self.at = [0.0] * 3
        self.child_at = [0.0] * 3
        self.absolute = False     # a 2D revolute angle measured from N


class Problem:
    """A problem with every constant-only quantity evaluated."""

    def __init__(self, data, overrides=None):
        _keys(data, "$", {"title", "dimension", "bodies", "joints"},
              {"format", "statement", "constants", "coordinates", "gravity", "points",
               "loads", "find", "simulate", "speeds", "impact"})
        # Declared generalized speeds change how the equations are written, not the motion:
        # the q'' compared here are the same, so `speeds` is read past. An `impact` changes
        # the rates after it, not the q'' at a state, so it is read past too.
        self.dimension = data["dimension"]
        if self.dimension not in (2, 3):
            raise ProblemError("$.dimension: expected 2 or 3")
        self.constants = {}
        for name, c in (data.get("constants") or {}).items():
            if isinstance(c, dict):
                _keys(c, f"constants.{name}", {"value"}, {"unit", "description", "vary", "step"})
                c = c["value"]
            self.constants[name] = float(c)
        for name, value in (overrides or {}).items():
            if name not in self.constants:
                raise ProblemError(f"--set: {name!r} is not a constant")
            self.constants[name] = float(value)
        self.declared_coords = data.get("coordinates") or {}
        for name, c in self.declared_coords.items():
            _keys(c, f"coordinates.{name}", set(), {"initial", "rate", "unit", "description"})
        self._read_bodies(data["bodies"])
        self._read_joints(data["joints"])
        self._read_points(data.get("points") or {})
        self.gravity = None
        if data.get("gravity") is not None:
            self.gravity = self._tree(data["gravity"], "gravity")
        self.loads = [self._read_load(l, f"loads[{i}]") for i, l in enumerate(data.get("loads") or [])]
        find = data.get("find") or {}
        # Questions are answered from q'' and reactions, which is what is compared here.
        _keys(find, "find", set(), {"reactions", "questions"})
        self.find = list(find.get("reactions") or [])
        for j in self.find:
            if j not in self.joint_by_name:
                raise ProblemError(f"find.reactions: unknown joint {j!r}")

    # ---- expressions ----

    def _tree(self, text, path):
        try:
            return ex.parse(text)
        except ex.ExprError as e:
            raise ProblemError(f"{path}: {e}") from None

    def const_lookup(self, name, primes, column):
        if primes == 0 and name in self.constants:
            return self.constants[name]
        if primes == 0 and name == "pi":
            return math.pi
        raise ex.ExprError(f"{name + chr(39) * primes!r} is not a constant", column)

    def scalar(self, text, path):
        """A constant-only scalar."""
        try:
            v = ex.evaluate(self._tree(text, path), self.const_lookup)
        except (ex.ExprError, ValueError, ZeroDivisionError, OverflowError) as e:
            raise ProblemError(f"{path}: {e}") from None
        if isinstance(v, ex.Vec):
            raise ProblemError(f"{path}: expected a scalar, found a vector")
        return v

    def local_vector(self, text, frame, path):
        """A constant-only vector written in `frame`'s unit vectors, as components there.

        Every frame is aligned with N when all coordinates are zero, so a unit vector of
        another frame is read as the same components in `frame` (a warning says so)."""
        if text is None:
            return [0.0, 0.0, 0.0]
        try:
            v = ex.evaluate(self._tree(text, path), self.const_lookup)
        except (ex.ExprError, ValueError, ZeroDivisionError, OverflowError) as e:
            raise ProblemError(f"{path}: {e}") from None
        if not isinstance(v, ex.Vec):
            if v == 0.0:
                return [0.0, 0.0, 0.0]
            raise ProblemError(f"{path}: expected a vector, found a scalar")
        out = [0.0, 0.0, 0.0]
        for f, c in v.parts.items():
            if f not in self.bodies and f != "N":
                raise ProblemError(f"{path}: unknown frame {f!r}")
            if f != frame:
                print(f"reference: warning: {path} uses {f}'s unit vectors; read as {frame}'s",
                      file=sys.stderr)
            out = [out[i] + c[i] for i in range(3)]
        return out

    # ---- sections ----

    def _read_bodies(self, bodies):
        if not isinstance(bodies, dict) or not bodies:
            raise ProblemError("bodies: expected at least one body")
        self.bodies = {}
        for name, b in bodies.items():
            path = f"bodies.{name}"
            # `shape` only says how the body is drawn.
            _keys(b, path, {"mass"}, {"center", "inertia", "description", "shape"})
            body = Body(name)
            body.mass = self.scalar(b["mass"], path + ".mass")
            self.bodies[name] = body
        for name, b in bodies.items():
            path = f"bodies.{name}"
            body = self.bodies[name]
            body.center = self.local_vector(b.get("center"), name, path + ".center")
            inertia = b.get("inertia", 0)
            if self.dimension == 2:
                body.inertia[2][2] = self.scalar(inertia, path + ".inertia")
            elif inertia != 0:
                _keys(inertia, path + ".inertia", set(), {"xx", "yy", "zz", "xy", "yz", "zx"})
                idx = {"xx": (0, 0), "yy": (1, 1), "zz": (2, 2), "xy": (0, 1), "yz": (1, 2), "zx": (2, 0)}
                for key, (i, j) in idx.items():
                    v = self.scalar(inertia.get(key, 0), f"{path}.inertia.{key}")
                    body.inertia[i][j] = v
                    body.inertia[j][i] = v

    def _read_joints(self, joints):
        self.coords = []
        self.joints = []
        self.joint_by_name = {}
        by_child = {}
        for i, j in enumerate(joints):
            path = f"joints[{i}]"
            _keys(j, path, {"name", "type", "parent", "child"},
                  {"coordinates", "axis", "sequence", "at", "child_at", "angle_from"})
            jt = j["type"]
            if jt not in JOINT_DOF:
                raise ProblemError(f"{path}.type: unknown joint type {jt!r}")
            if self.dimension == 2 and jt not in ("revolute", "prismatic", "planar", "weld"):
                raise ProblemError(f"{path}.type: {jt} is not allowed in 2D")
            for key in ("parent", "child"):
                if j[key] != "N" and j[key] not in self.bodies:
                    raise ProblemError(f"{path}.{key}: unknown body {j[key]!r}")
            if j["child"] == "N" or j["child"] in by_child:
                raise ProblemError(f"{path}.child: {j['child']!r} cannot be a child here")
            joint = Joint(j["name"], jt, j["parent"], j["child"])
            names = j.get("coordinates", [])
            if len(names) != JOINT_DOF[jt]:
                raise ProblemError(f"{path}.coordinates: {jt} needs {JOINT_DOF[jt]}")
            for n in names:
                if n in self.coords:
                    raise ProblemError(f"{path}.coordinates: {n!r} is used twice")
                self.coords.append(n)
                joint.coords.append(len(self.coords) - 1)
            if jt in ("revolute", "prismatic", "cylindrical"):
                if "axis" not in j:
                    raise ProblemError(f"{path}: missing key 'axis'")
                a = self.local_vector(j["axis"], joint.parent, path + ".axis")
                if norm(a) == 0.0:
                    raise ProblemError(f"{path}.axis: zero vector")
                joint.axis = vscale(1.0 / norm(a), a)
            elif "axis" in j:
                raise ProblemError(f"{path}.axis: not used by a {jt} joint")
            if jt in ("universal", "spherical", "free"):
                seq = j.get("sequence", "")
                want = 2 if jt == "universal" else 3
                if len(seq) != want or any(c not in "xyz" for c in seq):
                    raise ProblemError(f"{path}.sequence: expected {want} letters of xyz")
                joint.sequence = ["xyz".index(c) for c in seq]
            elif "sequence" in j:
                raise ProblemError(f"{path}.sequence: not used by a {jt} joint")
            # A planar revolute angle measured from N's axes rather than the parent's.
            joint.absolute = j.get("angle_from", joint.parent) == "N" and joint.parent != "N"
            if joint.absolute and (jt != "revolute" or self.dimension != 2):
                raise ProblemError(f"{path}.angle_from: only a 2D revolute angle is measured from N")
            joint.at = self.local_vector(j.get("at"), joint.parent, path + ".at")
            joint.child_at = self.local_vector(j.get("child_at"), joint.child, path + ".child_at")
            by_child[joint.child] = joint
            self.joints.append(joint)
            self.joint_by_name[joint.name] = joint
        # Tree order from N, so every parent is placed before its children.
        self.order = []
        placed = {"N"}
        pending = list(self.joints)
        while pending:
            ready = [jt for jt in pending if jt.parent in placed]
            if not ready:
                raise ProblemError("joints: some bodies are not connected to N")
            for jt in ready:
                self.order.append(jt)
                placed.add(jt.child)
                pending.remove(jt)
        missing = set(self.bodies) - placed
        if missing:
            raise ProblemError(f"joints: bodies without a joint: {sorted(missing)}")
        self.joint_of_child = by_child
        for name in self.declared_coords:
            if name not in self.coords:
                print(f"reference: warning: coordinate {name!r} is not named by a joint",
                      file=sys.stderr)

    def _read_points(self, points):
        self.points = {"N.o": ("N", [0.0, 0.0, 0.0])}
        for b, body in self.bodies.items():
            self.points[b + "*"] = (b, body.center)
            self.points[b + ".o"] = (b, [0.0, 0.0, 0.0])
        for j in self.joints:
            self.points[j.name] = (j.child, j.child_at)
        for name, p in points.items():
            path = f"points.{name}"
            _keys(p, path, {"on", "at"}, set())
            if p["on"] != "N" and p["on"] not in self.bodies:
                raise ProblemError(f"{path}.on: unknown body {p['on']!r}")
            self.points[name] = (p["on"], self.local_vector(p["at"], p["on"], path + ".at"))

    def _point(self, name, path):
        if name not in self.points:
            raise ProblemError(f"{path}: unknown point {name!r}")
        return self.points[name]

    def _body(self, name, path):
        if name != "N" and name not in self.bodies:
            raise ProblemError(f"{path}: unknown body {name!r}")
        return name

    def _read_load(self, l, path):
        if not isinstance(l, dict) or l.get("type") not in LOAD_KEYS:
            raise ProblemError(f"{path}.type: unknown load type")
        req, opt = LOAD_KEYS[l["type"]]
        _keys(l, path, req | {"type"}, opt | {"name"})
        ld = {"type": l["type"], "path": path}
        t = l["type"]
        if t == "force":
            ld["on"] = self._body(l["on"], path + ".on")
            ld["vector"] = self._tree(l["vector"], path + ".vector")
            at = l.get("at")
            if at is None:
                ld["point"] = self.points[ld["on"] + "*"] if ld["on"] != "N" else ("N", [0.0] * 3)
            elif isinstance(at, str) and at in self.points:
                ld["point"] = self.points[at]
            else:
                ld["point"] = (ld["on"], self.local_vector(at, ld["on"], path + ".at"))
        elif t == "torque":
            ld["on"] = self._body(l["on"], path + ".on")
            ld["vector"] = self._tree(l["vector"], path + ".vector")
            ld["reaction_on"] = None
            if l.get("reaction_on") is not None:
                ld["reaction_on"] = self._body(l["reaction_on"], path + ".reaction_on")
        elif t in ("spring", "damper"):
            pts = l["between"]
            if not isinstance(pts, list) or len(pts) != 2:
                raise ProblemError(f"{path}.between: expected two point names")
            ld["points"] = [self._point(p, f"{path}.between[{i}]") for i, p in enumerate(pts)]
            if t == "spring":
                ld["stiffness"] = self._tree(l["stiffness"], path + ".stiffness")
                ld["free_length"] = self._tree(l.get("free_length", 0), path + ".free_length")
            else:
                ld["coefficient"] = self._tree(l["coefficient"], path + ".coefficient")
        else:
            if l["joint"] not in self.joint_by_name:
                raise ProblemError(f"{path}.joint: unknown joint {l['joint']!r}")
            joint = self.joint_by_name[l["joint"]]
            names = [self.coords[i] for i in joint.coords]
            if l["coordinate"] not in names:
                raise ProblemError(f"{path}.coordinate: not a coordinate of {joint.name}")
            ld["joint"] = joint
            ld["index"] = names.index(l["coordinate"])
            for key in ("stiffness", "rest", "coefficient", "value"):
                if key in l or (key == "rest" and t == "joint_spring"):
                    ld[key] = self._tree(l.get(key, 0), f"{path}.{key}")
        return ld


def load(path, overrides=None):
    """Reads and prepares the problem file at `path`."""
    with open(path) as f:
        data = json.load(f)
    return Problem(data, overrides)
