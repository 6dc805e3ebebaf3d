#!/usr/bin/python3
"""Hostile-input probe of fluid_sim, fluid_sim_3d and the Python module `numerics`.

Runs about 190 cases in nine classes, each a bad (or deliberately odd but legitimate) input, and
classifies what the program did: clean, crash, hang, wrong exit code, unclear, silent, data loss.
See tests/hostile/README.md. Standard library only, plus the module `numerics` (each Python case
runs in its own interpreter, so that a crash of the module is seen as a crash, not as the
probe's own death).

    /usr/bin/python3 tests/hostile/probe.py [--bin DIR] [--python-path DIR] [--work DIR]
                                            [--jobs N] [--timeout S] [--only CLASS]
"""
import argparse
import concurrent.futures
import copy
import hashlib
import json
import math
import os
import random
import re
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import textwrap
import threading
import time

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))

CLASSES = ["mesh_files", "setup_scale", "python_args", "writable", "mesh_diag",
           "no_particles", "restart", "cli", "edge"]
OUTCOMES = ["clean", "crash", "hang", "wrong_exit", "unclear", "silent", "data_loss"]

# ---------------------------------------------------------------------------------------------
# Expectations


class Expect:
    """What a case should give.

    kind "refuse": exit code in `codes` (Python: an exception of a kind in `excs` whose
    exit_code is in `codes`), a one-line message holding every one of `words` (an entry that
    is a tuple: any one of its words). kind "accept": exit 0 (Python: no exception). kind
    "warn": a warning line holding `words` on stderr while running, or a refusal as for
    "refuse" with `codes`.
    """

    def __init__(self, kind, codes=(), words=(), excs=("RunError", "SceneError")):
        self.kind, self.codes, self.words, self.excs = kind, set(codes), list(words), set(excs)

    def describe(self):
        if self.kind == "accept":
            return "accept (exit 0)"
        w = ", ".join("|".join(x) if isinstance(x, tuple) else x for x in self.words)
        codes = "/".join(str(c) for c in sorted(self.codes))
        if self.kind == "warn":
            return f"warn [{w}] or refuse {codes}"
        return f"refuse {codes} [{w}]"


def refuse(code, *words, excs=("RunError", "SceneError")):
    codes = code if isinstance(code, (set, tuple, list)) else (code,)
    return Expect("refuse", codes, words, excs)


ACCEPT = Expect("accept")


def warn(*words, codes=(5,)):
    return Expect("warn", codes, words)


def names_all(message, words):
    low = message.lower()
    for w in words:
        alts = w if isinstance(w, tuple) else (w,)
        if not any(a.lower() in low for a in alts):
            return False
    return True


# ---------------------------------------------------------------------------------------------
# Scenes and files

TINY_2D = json.load(open(os.path.join(REPO, "tests/apps/scenes/tiny_2d.json")))
TINY_3D = json.load(open(os.path.join(REPO, "tests/apps/scenes/tiny_3d.json")))
QUIET_OUTPUT = {"every": 0.001, "formats": ["vtu"], "images": False, "video": False,
                "plots": []}


def tiny_scene(base, name, drop=None):
    """A copy of a tiny scene that writes little and has no probes, without the key `drop`."""
    j = copy.deepcopy(base)
    j["output"] = dict(QUIET_OUTPUT, directory=f"out/{name}")
    j["probes"] = []
    if drop:
        j.pop(drop)
    return j


def scene2d(bodies=True):
    return tiny_scene(TINY_2D, "tiny_2d", None if bodies else "bodies")


def scene3d(emitters=False):
    return tiny_scene(TINY_3D, "tiny_3d", None if emitters else "emitters")


# A unit cube, outward facing (0-based faces).
CUBE_V = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
CUBE_F = [(0, 2, 1), (0, 3, 2), (4, 5, 6), (4, 6, 7), (0, 1, 5), (0, 5, 4),
          (1, 2, 6), (1, 6, 5), (2, 3, 7), (2, 7, 6), (3, 0, 4), (3, 4, 7)]


def cube(side=0.12, at=(0.15, 0.15, 0.19)):
    return [tuple(at[i] + side * v[i] for i in range(3)) for v in CUBE_V], list(CUBE_F)


def scene_mesh(file="body.stl", extra=None):
    """A 3D scene of 0.4 m with a mesh body (the cube of `cube()`) above a layer of water."""
    j = scene3d()
    j["domain"] = {"min": [0, 0, 0], "max": [0.4, 0.4, 0.4]}
    j["fluids"][0]["max"] = [0.4, 0.4, 0.12]
    j["bodies"] = [dict({"name": "cup", "shape": "mesh", "file": file, "temperature": 60},
                        **(extra or {}))]
    return j


def fmt(x):
    return repr(float(x)) if isinstance(x, float) and math.isfinite(x) else str(x)


def stl_ascii(verts, faces):
    out = ["solid probe"]
    for f in faces:
        out += ["facet normal 0 0 0", " outer loop"]
        out += [" vertex " + " ".join(fmt(c) for c in verts[i]) for i in f]
        out += [" endloop", "endfacet"]
    return "\n".join(out + ["endsolid probe", ""]).encode()


def stl_binary(verts, faces):
    b = bytearray(b"probe binary stl".ljust(80, b" ") + struct.pack("<I", len(faces)))
    for f in faces:
        b += struct.pack("<3f", 0, 0, 0)
        for i in f:
            b += struct.pack("<3f", *verts[i])
        b += b"\0\0"
    return bytes(b)


def obj(verts, faces):
    lines = ["v " + " ".join(fmt(c) for c in v) for v in verts]
    lines += ["f " + " ".join(str(i + 1) for i in f) for f in faces]
    return ("\n".join(lines) + "\n").encode()


def ply_ascii(verts, faces, nverts=None, nfaces=None, end_header="end_header"):
    head = ["ply", "format ascii 1.0", f"element vertex {nverts if nverts is not None else len(verts)}",
            "property float x", "property float y", "property float z",
            f"element face {nfaces if nfaces is not None else len(faces)}",
            "property list uchar int vertex_indices", end_header]
    body = [" ".join(fmt(c) for c in v) for v in verts]
    body += [f"{len(f)} " + " ".join(str(i) for i in f) for f in faces]
    return ("\n".join(head + body) + "\n").encode()


def ply_binary(verts, faces, nverts=None, nfaces=None):
    head = ("ply\nformat binary_little_endian 1.0\n"
            f"element vertex {nverts if nverts is not None else len(verts)}\n"
            "property float x\nproperty float y\nproperty float z\n"
            f"element face {nfaces if nfaces is not None else len(faces)}\n"
            "property list uchar int vertex_indices\nend_header\n").encode()
    b = bytearray(head)
    for v in verts:
        b += struct.pack("<3f", *v)
    for f in faces:
        b += struct.pack("<B", len(f)) + struct.pack(f"<{len(f)}i", *f)
    return bytes(b)


def cylinder(n=64, r=0.06, z0=0.16, z1=0.3, c=(0.2, 0.2), seam=True):
    """A closed cylinder as independent triangles; the last sector's corner is computed at
    2*pi (sin = -2.4e-16), not reused from the first, so the seam differs by ~1e-16."""
    def ring(k, z):
        a = 2 * math.pi * k / n if seam else 2 * math.pi * (k % n) / n
        return (c[0] + r * math.cos(a), c[1] + r * math.sin(a), z)
    tris = []
    for k in range(n):
        a0, a1, b0, b1 = ring(k, z0), ring(k + 1, z0), ring(k, z1), ring(k + 1, z1)
        tris += [(a0, a1, b1), (a0, b1, b0), ((c[0], c[1], z0), a1, a0), ((c[0], c[1], z1), b0, b1)]
    verts = [p for t in tris for p in t]
    faces = [(3 * i, 3 * i + 1, 3 * i + 2) for i in range(len(tris))]
    return verts, faces


def circle_points(n, cx, cy, r):
    return [[round(cx + r * math.cos(2 * math.pi * k / n), 9),
             round(cy + r * math.sin(2 * math.pi * k / n), 9)] for k in range(n)]


def comb_polygon(n, translate, scale):
    """A polygon of n points: a zigzag top edge of integer coordinates (x = 0..n-3, y = 0 or 1)
    over a base 300000 units below: short numbers, so 1e6 points fit the 16 MiB of a scene."""
    pts = [[i, i % 2] for i in range(n - 2)] + [[n - 3, -300000], [0, -300000]]
    return {"shape": "polygon", "points": pts, "scale": scale, "translate": translate}


# ---------------------------------------------------------------------------------------------
# Running


class Ctx:
    def __init__(self, args):
        self.bin = args.bin
        self.fs2 = args.fs2
        self.fs3 = args.fs3
        self.pypath = args.python_path
        self.work = args.work
        self.timeout = args.timeout
        self.env = dict(os.environ)
        self.env["PYTHONPATH"] = self.pypath + os.pathsep + self.env.get("PYTHONPATH", "")
        self.env.pop("NUMERICS_TEST_SIGNAL", None)
        self.env.pop("NUMERICS_TEST_HOLD_STEP", None)

    def app(self, dim):
        return self.fs2 if dim == 2 else self.fs3


class Run:
    """What one process did."""

    def __init__(self, rc=None, out="", err="", timed_out=False):
        self.rc, self.out, self.err, self.timed_out = rc, out, err, timed_out


def run_proc(ctx, argv, cwd, timeout=None, stop_after=None, env=None):
    """Runs argv; `stop_after`: SIGTERM after that many seconds (a run that may go on long),
    which is not a timeout. Returns Run."""
    p = subprocess.Popen(argv, cwd=cwd, env=env or ctx.env, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, start_new_session=True)
    limit = timeout or ctx.timeout
    try:
        if stop_after is not None and stop_after < limit:
            try:
                out, err = p.communicate(timeout=stop_after)
                return Run(p.returncode, out.decode(errors="replace"), err.decode(errors="replace"))
            except subprocess.TimeoutExpired:
                os.kill(p.pid, signal.SIGTERM)
                try:
                    out, err = p.communicate(timeout=15)
                except subprocess.TimeoutExpired:
                    os.killpg(p.pid, signal.SIGKILL)
                    out, err = p.communicate()
                    return Run(None, out.decode(errors="replace"), err.decode(errors="replace"),
                               True)
                r = Run(p.returncode, out.decode(errors="replace"), err.decode(errors="replace"))
                r.stopped = True
                return r
        out, err = p.communicate(timeout=limit)
        return Run(p.returncode, out.decode(errors="replace"), err.decode(errors="replace"))
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        out, err = p.communicate()
        return Run(None, out.decode(errors="replace"), err.decode(errors="replace"), True)


PROGRESS = re.compile(r"^\s*(\d+(\.\d+)?\s*%|\[?=*>|t = .* s.*step|step \d+)", re.I)


def message_lines(text):
    lines = []
    for raw in text.splitlines():
        line = raw.split("\r")[-1].strip()
        if line and not PROGRESS.match(line):
            lines.append(line)
    return lines


def checksums(folder):
    sums = {}
    for root, _, files in os.walk(folder):
        for f in files:
            if f == ".numerics.lock":  # the lock file holds the last run's pid; not data
                continue
            path = os.path.join(root, f)
            with open(path, "rb") as fh:
                sums[os.path.relpath(path, folder)] = hashlib.sha256(fh.read()).hexdigest()
    return sums


def lost_files(before, folder):
    after = checksums(folder) if os.path.isdir(folder) else {}
    return sorted(k for k, v in before.items() if after.get(k) != v)


class Result:
    def __init__(self, outcome, rc, message, note=""):
        self.outcome, self.rc, self.message, self.note = outcome, rc, message, note


def classify_cli(expect, r, lost=()):
    """Classifies one app run against its expectation."""
    text = r.err if r.err.strip() else r.out
    lines = message_lines(r.err) if r.err.strip() else message_lines(r.out)
    first = " | ".join(lines)[:2000]
    every = r.err + r.out
    if lost:
        return Result("data_loss", r.rc, first, "changed or removed: " + ", ".join(lost[:5]))
    if r.timed_out:
        return Result("hang", None, first, "timed out")
    if r.rc is not None and (r.rc < 0 or r.rc in (134, 139)):
        return Result("crash", r.rc, first, "killed by a signal")
    if re.search(r"internal error|please report", every, re.I):
        return Result("crash", r.rc, first, "internal error")
    stopped = getattr(r, "stopped", False)
    if expect.kind == "warn":
        warnings = [l for l in message_lines(r.err) if "warning" in l.lower()]
        if any(names_all(w, expect.words) for w in warnings):
            return Result("clean", r.rc, " | ".join(warnings)[:2000])
        if r.rc in expect.codes:
            if len(lines) == 1 and names_all(lines[0], expect.words):
                return Result("clean", r.rc, first)
            return Result("unclear", r.rc, first)
        if r.rc == 0 or stopped:
            return Result("silent", r.rc, first, "ran without the warning")
        return Result("wrong_exit", r.rc, first)
    if expect.kind == "accept":
        if r.rc == 0:
            return Result("clean", 0, first)
        return Result("wrong_exit", r.rc, first, "expected exit 0")
    # refuse
    if r.rc == 0:
        return Result("silent", 0, first, "accepted a bad input")
    if r.rc not in expect.codes:
        return Result("wrong_exit", r.rc, first)
    if len(lines) != 1:
        return Result("unclear", r.rc, first, f"{len(lines)} lines")
    if not names_all(lines[0], expect.words):
        return Result("unclear", r.rc, first, "does not name " + expect.describe())
    return Result("clean", r.rc, first)


PY_HEAD = """\
import json, math, os, sys, threading, time
import numerics
RES = {}
def done():
    print("@@RESULT@@" + json.dumps(RES), flush=True)
try:
%s
    RES["ok"] = True
except numerics.Error as e:
    RES.update(exc=type(e).__name__, exit_code=getattr(e, "exit_code", None), msg=str(e))
except Exception as e:
    RES.update(exc=type(e).__name__, exit_code=None, msg=str(e))
done()
"""


def run_python(ctx, code, cwd, timeout=None):
    path = os.path.join(cwd, "case.py")
    with open(path, "w") as f:
        f.write(PY_HEAD % textwrap.indent(textwrap.dedent(code).strip("\n"), "    "))
    return run_proc(ctx, [sys.executable, path], cwd, timeout=timeout)


def classify_py(expect, r, lost=()):
    res = None
    for line in r.out.splitlines():
        if line.startswith("@@RESULT@@"):
            res = json.loads(line[len("@@RESULT@@"):])
    if lost:
        return Result("data_loss", r.rc, (res or {}).get("msg", "")[:300],
                      "changed or removed: " + ", ".join(lost[:5]))
    if r.timed_out:
        return Result("hang", None, "", "timed out")
    tail = message_lines(r.err)[-1:] or [""]
    if r.rc is not None and (r.rc < 0 or r.rc in (134, 139)):
        return Result("crash", r.rc, tail[0], "interpreter killed by a signal")
    if res is None:
        return Result("crash", r.rc, tail[0], "interpreter ended without a result")
    msg = res.get("msg", "")
    code = res.get("exit_code")
    shown = f"{res.get('exc', 'ok')}({code}): {msg}" if "exc" in res else "no exception"
    if re.search(r"internal error|please report", msg, re.I):
        return Result("crash", code, shown, "internal error")
    if expect.kind == "accept":
        return Result("clean" if res.get("ok") else "wrong_exit", code, shown)
    if expect.kind == "warn":
        warnings = [l for l in message_lines(r.err) if "warning" in l.lower()]
        if any(names_all(w, expect.words) for w in warnings):
            return Result("clean", code, " | ".join(warnings)[:300])
        if res.get("ok"):
            return Result("silent", 0, shown, "ran without the warning")
    if res.get("ok"):
        return Result("silent", 0, shown, "no exception")
    if res["exc"] not in expect.excs or (expect.codes and code not in expect.codes):
        return Result("wrong_exit", code, shown, "expected " + "/".join(sorted(expect.excs)))
    if "\n" in msg.strip():
        return Result("unclear", code, shown, "message of several lines")
    words = [w.replace("{particle}", str(res.get("particle"))) if isinstance(w, str) else w
             for w in expect.words]
    if not names_all(msg, words):
        return Result("unclear", code, shown, "does not name " + expect.describe())
    return Result("clean", code, shown)


# ---------------------------------------------------------------------------------------------
# Cases


class Case:
    def __init__(self, cls, name, expect, fn, repro=""):
        self.cls, self.name, self.expect, self.fn = cls, name, expect, fn
        self.repro = repro


CASES = []


def case(cls, name, expect):
    def wrap(fn):
        CASES.append(Case(cls, name, expect, fn))
        return fn
    return wrap


def write(dirpath, name, data):
    path = os.path.join(dirpath, name)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)
    return path


def prior_output(ctx, d, dim):
    """A good first run into <d>/out; returns (folder, checksums)."""
    folder = os.path.join(d, "out")
    write(d, "good.json", json.dumps(scene2d() if dim == 2 else scene3d()))
    r = run_proc(ctx, [ctx.app(dim), "good.json", "--out", folder, "--end-time", "0.002",
                       "--quiet", "--threads", "1"], d)
    if r.rc != 0:
        raise RuntimeError(f"the prior good run failed: {r.rc} {r.err[-300:]}")
    return folder, checksums(folder)


def cli_case(cls, name, expect, scene=None, files=None, args=(), dim=None, prior=False,
             raw=None, quiet=True, stop_after=None, setup=None, end_time="0.002", bare=False):
    """A case that runs an app on a scene written as <dir>/scene.json with `files` beside it."""
    dim = dim or (scene or {}).get("dimension", 2)

    def fn(ctx, d):
        for fname, data in (files or {}).items():
            write(d, fname, data)
        if setup:
            setup(d)
        argv = [ctx.app(dim)]
        if bare:  # the command line exactly as given (a scene is written as scene.json)
            if scene is not None:
                write(d, "scene.json", json.dumps(scene))
            argv += list(args)
            r = run_proc(ctx, argv, d)
            res = classify_cli(expect, r)
            res.repro = "cd " + d + " && " + " ".join(shq(a) for a in argv)
            return res
        if scene is not None or raw is not None:
            write(d, "scene.json", raw if raw is not None else json.dumps(scene))
            argv.append("scene.json")
        if end_time:
            argv += ["--end-time", end_time]
        argv += ["--threads", "1"] + (["--quiet"] if quiet else [])
        before = None
        if prior:
            folder, before = prior_output(ctx, d, dim)
            argv += ["--out", folder]
        elif "--out" not in args:
            argv += ["--out", os.path.join(d, "out")]
        argv += [a.replace("@D", d) for a in args]
        r = run_proc(ctx, argv, d, stop_after=stop_after)
        lost = lost_files(before, folder) if before is not None else ()
        res = classify_cli(expect, r, lost)
        res.repro = "cd " + d + " && " + " ".join(shq(a) for a in argv)
        return res

    CASES.append(Case(cls, name, expect, fn))


def py_case(cls, name, expect, code, scene=None, files=None, prior=False, dim=2):
    """A case run as a Python script in its own interpreter; the code sees SCENE (the scene
    file's path), OUT (an output folder) and D (the case's folder)."""

    def fn(ctx, d):
        for fname, data in (files or {}).items():
            write(d, fname, data)
        sc = scene if scene is not None else (scene2d() if dim == 2 else scene3d())
        write(d, "scene.json", json.dumps(sc))
        before = None
        out = os.path.join(d, "out")
        if prior:
            out, before = prior_output(ctx, d, dim)
        pre = f"SCENE = {os.path.join(d, 'scene.json')!r}\nOUT = {out!r}\nD = {d!r}\n"
        r = run_python(ctx, pre + textwrap.dedent(code), d)
        lost = lost_files(before, out) if before is not None else ()
        res = classify_py(expect, r, lost)
        res.repro = f"cd {d} && PYTHONPATH={ctx.pypath} {sys.executable} case.py"
        return res

    CASES.append(Case(cls, name, expect, fn))


def shq(a):
    return a if re.fullmatch(r"[\w@%+=:,./-]+", a) else "'" + a.replace("'", "'\\''") + "'"


# ----- 1. mesh files --------------------------------------------------------------------------

def mesh_files():
    C = "mesh_files"
    v, f = cube()
    good = {"stl_ascii": ("body.stl", stl_ascii(v, f)), "stl_binary": ("body.stl", stl_binary(v, f)),
            "obj": ("body.obj", obj(v, f)), "ply_ascii": ("body.ply", ply_ascii(v, f)),
            "ply_binary": ("body.ply", ply_binary(v, f))}
    for kind, (name, data) in good.items():
        cli_case(C, f"good_{kind}", ACCEPT, scene_mesh(name), {name: data})
    bad = broken_mesh_files(v, f)
    for name, (fname, data) in bad.items():
        cli_case(C, name, refuse(5, "bodies[0]", fname), scene_mesh(fname), {fname: data},
                 prior=name in ("ply_ascii_truncated", "garbage_stl"))

    mesh_files_odd_paths(C, v, f)
    mesh_files_python(C, v, f)


def broken_mesh_files(v, f):
    """The broken (or not-a-mesh) files of mesh_files, by case name: (file name, bytes)."""
    bad = {}
    pa, pb = ply_ascii(v, f), ply_binary(v, f)
    bad["ply_ascii_truncated"] = ("body.ply", pa[: len(pa) * 2 // 3])
    bad["ply_binary_truncated"] = ("body.ply", pb[: len(pb) - 17])
    sb = stl_binary(v, f)
    bad["stl_binary_truncated"] = ("body.stl", sb[: len(sb) - 30])
    sa = stl_ascii(v, f)
    bad["stl_ascii_truncated"] = ("body.stl", sa[: len(sa) // 2])
    bad["obj_truncated"] = ("body.obj", obj(v, f[:9]) + b"f 1 2")
    bad["ply_end_header_misspelt"] = ("body.ply", ply_ascii(v, f, end_header="end_headr"))
    bad["ply_2e9_vertices"] = ("body.ply", ply_ascii(v, f, nverts=2000000000))
    bad["ply_binary_2e9_faces"] = ("body.ply", ply_binary(v, f, nfaces=2000000000))
    bad["ply_face_255_corners"] = ("body.ply", ply_ascii(v, f[:11] + [tuple(i % 8 for i in range(255))]))
    bad["ply_index_out_of_range"] = ("body.ply", ply_ascii(v, f[:11] + [(3, 4, 8)]))
    bad["ply_negative_index"] = ("body.ply", ply_ascii(v, f[:11] + [(3, -4, 7)]))
    bad["ply_header_1000_faces_12_present"] = ("body.ply", ply_ascii(v, f, nfaces=1000))
    bad["ply_binary_1000_faces_12_present"] = ("body.ply", ply_binary(v, f, nfaces=1000))
    bad["ply_words_for_numbers"] = ("body.ply", ply_ascii(v, f).replace(b"0.15 ", b"abc ", 1))
    bad["obj_index_77_of_8"] = ("body.obj", obj(v, f[:11]) + b"f 4 5 77\n")
    bad["obj_index_zero"] = ("body.obj", obj(v, f[:11]) + b"f 0 4 5\n")
    bad["empty_ascii_stl"] = ("body.stl", b"solid x\nendsolid x\n")
    bad["empty_file"] = ("body.stl", b"")
    random.seed(7)
    bad["garbage_stl"] = ("body.stl", bytes(random.randrange(256) for _ in range(3000)))
    bad["garbage_obj"] = ("body.obj", bytes(random.randrange(256) for _ in range(3000)))
    bad["binary_stl_count_1e9"] = ("body.stl", sb[:80] + struct.pack("<I", 10**9) + sb[84:])
    nan_v = list(v)
    nan_v[6] = (float("nan"), 0.27, 0.31)
    bad["stl_ascii_nan_vertex"] = ("body.stl", stl_ascii(nan_v, f))
    inf_v = list(v)
    inf_v[2] = (0.27, float("inf"), 0.19)
    bad["stl_binary_inf_vertex"] = ("body.stl", stl_binary(inf_v, f))
    bad["text_file_named_ply"] = ("body.ply", b"this is not a mesh\n")
    return bad


def mesh_files_odd_paths(C, v, f):
    """mesh_files' cases of a mesh that is missing, a directory, a FIFO, /dev/zero or cut short."""
    pa = ply_ascii(v, f)
    cli_case(C, "missing_file", refuse(5, "bodies[0]", "nowhere.stl"), scene_mesh("nowhere.stl"))
    cli_case(C, "directory_as_mesh", refuse(5, "bodies[0]", "dir.stl"), scene_mesh("dir.stl"),
             setup=lambda d: os.makedirs(os.path.join(d, "dir.stl")))
    cli_case(C, "fifo_as_mesh", refuse(5, "bodies[0]", "pipe.stl"), scene_mesh("pipe.stl"),
             setup=lambda d: os.mkfifo(os.path.join(d, "pipe.stl")), prior=True)
    cli_case(C, "dev_zero_as_mesh", refuse(5, "bodies[0]", "zero.stl"), scene_mesh("zero.stl"),
             setup=lambda d: os.symlink("/dev/zero", os.path.join(d, "zero.stl")))
    sec = scene2d(bodies=False)
    sec["bodies"] = [{"shape": "section", "file": "body.ply", "axis": "y", "at": 0.2,
                      "translate": [-0.1, -0.15]}]
    cli_case(C, "section_2d_of_truncated_ply", refuse(5, "bodies[0]", "body.ply"), sec,
             {"body.ply": pa[: len(pa) // 2]})
    sec2 = copy.deepcopy(sec)
    sec2["bodies"][0]["file"] = "pipe.obj"
    cli_case(C, "section_2d_of_fifo", refuse(5, "bodies[0]", "pipe.obj"), sec2,
             setup=lambda d: os.mkfifo(os.path.join(d, "pipe.obj")))


def mesh_files_python(C, v, f):
    """mesh_files' cases through Python, each in its own interpreter."""
    pb, sb = ply_binary(v, f), stl_binary(v, f)
    nan_v = list(v)
    nan_v[6] = (float("nan"), 0.27, 0.31)
    # Scene.load(path).check(), and one Simulation.
    check = "numerics.Scene.load(SCENE).check()\n"
    py_cases = {
        "py_ply_truncated": ("body.ply", pb[: len(pb) // 2], None),
        "py_ply_2e9_vertices": ("body.ply", ply_ascii(v, f, nverts=2000000000), None),
        "py_garbage_stl": ("body.stl", bytes(random.randrange(256) for _ in range(2000)), None),
        "py_obj_index_77": ("body.obj", obj(v, f[:11]) + b"f 4 5 77\n", None),
        "py_empty_file": ("body.obj", b"", None),
        "py_face_255_corners": ("body.ply", ply_ascii(v, f[:11] + [tuple(i % 8 for i in range(255))]), None),
        "py_nan_vertex": ("body.stl", stl_ascii(nan_v, f), None),
        "py_fifo": ("pipe.stl", None, "fifo"),
        "py_directory": ("dir.ply", None, "dir"),
    }
    for name, (fname, data, special) in py_cases.items():
        pre = ""
        if special == "fifo":
            pre = f"os.mkfifo(os.path.join(D, {fname!r}))\n"
        elif special == "dir":
            pre = f"os.makedirs(os.path.join(D, {fname!r}))\n"
        py_case(C, name, refuse(5, fname, excs=("SceneError",)), pre + check,
                scene=scene_mesh(fname), files={fname: data} if data is not None else None)
    py_case(C, "py_simulation_truncated_stl", refuse(5, "bodies[0]", "body.stl", excs=("SceneError",)),
            "numerics.Simulation(SCENE, out=OUT, threads=1, quiet=True)\n",
            scene=scene_mesh("body.stl"), files={"body.stl": sb[:200]}, prior=True, dim=3)


# ----- 2. set-up scale -------------------------------------------------------------------------

def setup_scale():
    C = "setup_scale"
    j = scene2d(bodies=False)
    j["fluids"] = [{"material": "water", "shape": "polygon",
                    "points": circle_points(100000, 0.08, 0.07, 0.06)}]
    cli_case(C, "fluid_polygon_1e5", ACCEPT, j)
    j = scene2d(bodies=False)
    j["bodies"] = [{"shape": "polygon", "points": circle_points(100000, 0.15, 0.05, 0.03)}]
    cli_case(C, "body_polygon_1e5", ACCEPT, j)
    j = scene2d(bodies=False)
    j["walls"] = [{"shape": "polygon", "points": circle_points(100000, 0.16, 0.16, 0.025)}]
    cli_case(C, "wall_polygon_1e5", ACCEPT, j)
    j = scene2d(bodies=False)
    pts = [[round(0.12 + 0.07 * k / 99999, 9), round(0.15 + 0.01 * math.sin(k / 500), 9)]
           for k in range(100000)]
    j["walls"] = [{"shape": "polyline", "points": pts, "thickness": 0.02}]
    cli_case(C, "wall_polyline_1e5", ACCEPT, j)
    j = scene2d(bodies=False)
    j["fluids"] = [dict(comb_polygon(1000000, [0.01, 0.064], 1.8e-7), material="water")]
    cli_case(C, "fluid_polygon_1e6", ACCEPT, j)
    j = scene2d(bodies=False)
    j["bodies"] = [comb_polygon(1000000, [0.12, 0.031], 7e-8)]
    cli_case(C, "body_polygon_1e6", ACCEPT, j)
    j = scene2d(bodies=False)
    pts = circle_points(100000, 0.15, 0.05, 0.03)
    pts[50000], pts[50001] = pts[50001], pts[50000]  # two edges cross
    j["bodies"] = [{"shape": "polygon", "points": pts}]
    cli_case(C, "self_crossing_polygon_1e5", refuse(5, "bodies[0]", "edge"), j)
    j = scene2d(bodies=False)
    poly = comb_polygon(1000000, [0.12, 0.031], 7e-8)
    poly["points"][400000], poly["points"][400002] = poly["points"][400002], poly["points"][400000]
    poly["points"][400000] = [400002, -5]
    j["bodies"] = [poly]
    cli_case(C, "self_crossing_polygon_1e6", refuse(5, "bodies[0]", "edge"), j)
    setup_scale_limits(C)


def setup_scale_limits(C):
    """setup_scale's cases at the limits: the lattice, the particles, the outputs and checkpoints."""
    # Lattice limit: 2e8 points over the domain and its walls.
    j = scene2d(bodies=False)
    j["domain"]["max"] = [1.4, 1.4]
    j["boundaries"]["y_max"] = {"type": "wall"}
    j["particles"]["spacing"] = 1e-4
    j["fluids"][0]["min"], j["fluids"][0]["max"] = [0, 0], [0.01, 0.01]
    j["fluids"][0]["temperature"], j["fluids"][0]["velocity"] = 20, [0, 0]
    j["output"]["every"] = 1e-5
    cli_case(C, "just_under_lattice_limit_2d", ACCEPT, j, end_time="1e-5")
    j2 = copy.deepcopy(j)
    j2["domain"]["max"] = [1.42, 1.42]
    cli_case(C, "just_over_lattice_limit_2d", refuse(5, "particles.spacing", "lattice"), j2,
             end_time="1e-5")
    j3 = scene3d()
    j3["domain"]["max"] = [1, 1, 1]
    j3["fluids"][0]["max"] = [1, 1, 1]
    j3["particles"]["spacing"] = 0.0035
    cli_case(C, "over_particle_limit_3d", refuse(5, "particles.spacing", ("20 million", "2e+07", "memory")),
             j3, end_time="1e-5")
    j4 = scene3d(emitters=True)
    j4["output"]["every"] = 1e4
    cli_case(C, "emitter_over_particle_limit", refuse(5, ("emitters", "particles")), j4,
             end_time="1e6")
    j5 = scene2d()
    j5["output"]["every"] = 1e-9
    cli_case(C, "outputs_over_limit", refuse(5, "output.every"), j5, end_time="0.02")
    cli_case(C, "checkpoints_over_limit", refuse(2, "--checkpoint-every"), scene2d(),
             args=["--checkpoint-every", "1e-9"], end_time="0.02")
    j6 = scene3d()
    j6["domain"]["max"] = [3, 3, 3]
    j6["particles"]["spacing"] = 0.004
    j6["fluids"][0]["max"] = [0.05, 0.05, 0.05]
    cli_case(C, "over_lattice_limit_3d_small_fluid", refuse(5, "particles.spacing"), j6,
             end_time="1e-5")


# ----- 3. Python arguments ---------------------------------------------------------------------

def python_args():
    C = "python_args"
    mk = "sim = numerics.Simulation(SCENE, threads=1, out=OUT, quiet=True, end_time=0.004)\n"
    runs = {"until_nan": ("until", "until=math.nan"), "until_inf": ("until", "until=math.inf"),
            "until_minus_1": ("until", "until=-1"), "until_str": ("until", "until='1'"),
            "every_1e-300": ("every", "every=1e-300"), "every_minus_1": ("every", "every=-1"),
            "every_nan": ("every", "every=math.nan"), "callback_3": ("callback", "callback=3"),
            "progress_str": ("progress", "progress='no'"),
            "until_list": ("until", "until=[1]")}
    for name, (param, kw) in runs.items():
        extra = "" if "progress" in kw else ", progress=False"
        py_case(C, "run_" + name, refuse(2, param + ":", excs=("RunError",)),
                mk + f"sim.run({kw}{extra})\n")
    sims = {"scene_42": ("scene", "42"),
            "end_time_str": ("end_time", "SCENE, end_time='1'"),
            "end_time_nan": ("end_time", "SCENE, end_time=math.nan"),
            "end_time_minus_1": ("end_time", "SCENE, end_time=-1"),
            "threads_minus_1": ("threads", "SCENE, threads=-1"),
            "threads_1.5": ("threads", "SCENE, threads=1.5"),
            "threads_str": ("threads", "SCENE, threads='2'"),
            "threads_1e6": ("threads", "SCENE, threads=10**6"),
            "out_42": ("out", "SCENE, out=42"),
            "out_empty": ("out", "SCENE, out=''"),
            "backend_gpu": ("backend", "SCENE, backend='gpu'"),
            "quiet_str": ("quiet", "SCENE, quiet='yes'")}
    for name, (param, a) in sims.items():
        kw = ""
        if "out=" not in a and a != "42":
            kw = ", out=OUT"
        py_case(C, "sim_" + name, refuse(2, param + ":", excs=("RunError",)),
                f"numerics.Simulation({a}{kw})\n")
    py_case(C, "scene_load_42", refuse(2, "path", excs=("SceneError",)), "numerics.Scene.load(42)\n")
    py_case(C, "scene_set_nan", refuse(2, "value", excs=("SceneError",)),
            "numerics.Scene.load(SCENE).set('particles.spacing', math.nan)\n")
    py_case(C, "scene_set_path_int", refuse(2, "path", excs=("SceneError",)),
            "numerics.Scene.load(SCENE).set(3, 1)\n")
    py_case(C, "set_body_velocity_unknown", refuse(2, "nobody", excs=("RunError",)),
            mk + "sim.set_body_velocity('nobody', [0, 0])\n")
    py_case(C, "until_beyond_end_is_fine", ACCEPT, mk + "sim.run(until=1e300, progress=False)\n")


# ----- 4. writes through particles_writable() --------------------------------------------------

def writable():
    C = "writable"
    head = ("sim = numerics.Simulation(SCENE, threads=1, out=OUT, quiet=True, end_time=0.01)\n"
            "w = sim.particles_writable()\n"
            "import numpy as np\n"
            "i = int(np.flatnonzero(w.kind == 0)[3])\n")
    writes = {
        "material_1e9": ("material", "w.material[i] = 1000000000"),
        "material_2": ("material", "w.material[i] = 2"),
        "material_minus_1": ("material", "w.material[i] = -1"),
        "velocity_inf": ("velocity", "w.velocity[i, 0] = math.inf"),
        "velocity_nan": ("velocity", "w.velocity[i, 1] = math.nan"),
        "velocity_supersonic": ("velocity", "w.velocity[i] = [1000.0, 0.0]"),
        "kind_99": ("kind", "w.kind[i] = 99"),
        "id_changed": ("id", "w.id[i] = w.id[i] + 100000"),
        "mass_0": ("mass", "w.mass[i] = 0"),
        "density_negative": ("density", "w.density[i] = -1000"),
        "density_3x_rest": ("density", "w.density[i] = 3000"),
        "pressure_inf": ("pressure", "w.pressure[i] = math.inf"),
        "temperature_nan_all": ("temperature", "w.temperature = math.nan"),
        "position_nan_wall": ("position", "j = int(np.flatnonzero(w.kind == 1)[0]); RES['particle'] = int(w.id[j]); w.position[j, 0] = math.nan"),
        "position_beyond_x_max_wall": ("position", "w.position[i] = [0.3, 0.05]"),
        "position_3_m_below_the_floor": ("position", "w.position[i] = [0.05, -3.0]"),
        "temperature_below_absolute_zero": ("temperature", "w.temperature[i] = -500.0"),
    }
    for name, (q, stmt) in writes.items():
        codes = (2, 9) if name == "temperature_below_absolute_zero" else (2,)
        who = "particle" if name == "temperature_nan_all" else "particle {particle}"
        py_case(C, name, refuse(codes, q, who, excs=("RunError",)),
                head + "RES['particle'] = int(w.id[i])\n" + stmt + "\nsim.step()\n")
    py_case(C, "shape_mismatch", refuse((None,), "shape", excs=("ValueError",)),
            head + "w.velocity = np.zeros(3 * len(w) + 1)\n")
    py_case(C, "read_only_view", refuse((None,), "read-only", excs=("ValueError",)),
            head + "sim.particles.temperature[i] = 5.0\n")
    py_case(C, "write_back_and_go_on", ACCEPT,
            head + "v = w.velocity[i].copy()\nw.velocity[i, 0] = math.nan\n"
                   "try:\n    sim.step()\nexcept numerics.RunError:\n    pass\n"
                   "w = sim.particles_writable()\nw.velocity[i] = v\nsim.step()\n")
    py_case(C, "stale_view_after_step", refuse(2, ("step", "again", "stale"),
                                                excs=("StaleParticlesError",)),
            head + "sim.step()\nw.temperature[i] = 30.0\n")


# ----- 5. mesh diagnostics ---------------------------------------------------------------------

def mesh_diag():
    C = "mesh_diag"
    v, f = cube()
    nan_v = list(v)
    nan_v[5] = (0.27, float("nan"), 0.31)
    cli_case(C, "obj_nan_vertex", refuse(5, "bodies[0]", "triangle", ("nan", "finite")),
             scene_mesh("body.obj"), {"body.obj": obj(nan_v, f)}, prior=True)
    inf_v = list(v)
    inf_v[0] = (float("-inf"), 0.15, 0.19)
    cli_case(C, "ply_inf_vertex", refuse(5, "bodies[0]", "triangle", ("inf", "finite")),
             scene_mesh("body.ply"), {"body.ply": ply_ascii(inf_v, f)})
    cli_case(C, "ply_index_9_of_8", refuse(5, "bodies[0]", "9", "8"), scene_mesh("body.ply"),
             {"body.ply": ply_ascii(v, f[:11] + [(3, 9, 7)])})
    cv, cf = cylinder()
    cli_case(C, "cylinder_seam_1e-16_stl", ACCEPT, scene_mesh("cyl.stl"),
             {"cyl.stl": stl_ascii(cv, cf)})
    cli_case(C, "cylinder_seam_1e-16_obj", ACCEPT, scene_mesh("cyl.obj"),
             {"cyl.obj": obj(cv, cf)})
    cli_case(C, "cylinder_seam_1e-16_ply", ACCEPT, scene_mesh("cyl.ply"),
             {"cyl.ply": ply_ascii(cv, cf)})
    cv2, cf2 = cylinder(n=256)
    cli_case(C, "cylinder_256_sectors_binary_stl", ACCEPT, scene_mesh("cyl.stl"),
             {"cyl.stl": stl_binary(cv2, cf2)})
    good = {"body.stl": stl_ascii(v, f)}
    for name, extra, words in [
            ("translate_1e300", {"translate": [1e300, 0, 0]}, ("inside the domain",)),
            ("translate_minus_1e300", {"translate": [0, 0, -1e300]}, ("inside the domain",)),
            ("scale_1e-300", {"scale": 1e-300}, (("scale", "particle", "spacing"),)),
            ("scale_1e300", {"scale": 1e300}, (("scale", "inside", "overflow", "finite"),)),
            ("scale_0", {"scale": 0}, ("scale",)),
            ("rotate_string_nan", {"rotate": "nan"}, ("rotate",)),
            ("rotate_1e308", {"rotate": [0, 0, 1e308]}, ("rotate",))]:
        cli_case(C, name, refuse(5, "bodies[0]", *words), scene_mesh("body.stl", extra), good)
    cli_case(C, "rotate_nan_via_set", refuse(5, "bodies[0]", "rotate"),
             scene_mesh("body.stl"), good, args=["--set", "bodies.0.rotate=[0,0,NaN]"])
    raw = json.dumps(scene_mesh("body.stl", {"rotate": [0, 0, 12345]})).replace("12345", "NaN")
    cli_case(C, "rotate_nan_literal_in_json", refuse(4, "scene.json"), raw=raw, files=good, dim=3)
    mesh_diag_topology(C, v, f, good)


def mesh_diag_topology(C, v, f, good):
    """mesh_diag's faulty meshes (open, non-manifold, mis-oriented, ...) and a section that misses."""
    cli_case(C, "open_mesh", refuse(5, "bodies[0]", "not closed", "open edge"),
             scene_mesh("body.stl"), {"body.stl": stl_ascii(v, f[:11])})
    cli_case(C, "non_manifold", refuse(5, "bodies[0]", "manifold"), scene_mesh("body.stl"),
             {"body.stl": stl_ascii(v, f + [f[0]])})
    flipped = list(f)
    flipped[4] = tuple(reversed(f[4]))
    cli_case(C, "inconsistent_orientation", refuse(5, "bodies[0]", "oriented"),
             scene_mesh("body.obj"), {"body.obj": obj(v, flipped)})
    v2, f2 = cube(0.12, (0.2, 0.2, 0.23))
    both = list(v) + list(v2)
    cli_case(C, "self_intersecting", refuse(5, "bodies[0]", "intersects itself"),
             scene_mesh("body.obj"), {"body.obj": obj(both, f + [tuple(i + 8 for i in t) for t in f2])})
    vz = list(v) + [((v[0][0] + v[1][0]) / 2, v[0][1], v[0][2])]
    fz = [f[0], f[1]] + [t for t in f[2:]] + [(0, 8, 1)]
    cli_case(C, "zero_area_triangle", refuse(5, "bodies[0]", ("zero area", "degenerate", "not closed")),
             scene_mesh("body.obj"), {"body.obj": obj(vz, fz)})
    inward = [tuple(reversed(t)) for t in f]
    cli_case(C, "all_inward_is_fine", ACCEPT, scene_mesh("body.stl"),
             {"body.stl": stl_ascii(v, inward)})
    # A mesh in millimetres: as a body it misses the domain (refused, docs/scenes.md); as a
    # fluid volume that meets the domain it fills it, with the warning naming the scale.
    mm = [tuple(c * 1000 for c in p) for p in v]
    cli_case(C, "mesh_in_millimetres_body", refuse(5, "bodies[0]", ("scale", "inside the domain")),
             scene_mesh("body.stl"), {"body.stl": stl_ascii(mm, f)})
    mmv, _ = cube(side=120.0, at=(0.0, 0.0, 0.0))
    jf = scene3d()
    jf["domain"]["max"] = [0.4, 0.4, 0.4]
    jf["fluids"] = [{"material": "water", "shape": "mesh", "file": "water.stl"}]
    cli_case(C, "mesh_in_millimetres_fluid", warn("fluids[0]", "scale"), jf,
             {"water.stl": stl_ascii(mmv, f)}, quiet=False, stop_after=20)
    j = scene2d(bodies=False)
    j["bodies"] = [{"shape": "section", "file": "body.stl", "axis": "y", "at": 5.0}]
    cli_case(C, "section_plane_misses", refuse(5, "bodies[0]", ("miss", "cut", "plane")), j, good)


# ----- 6. geometry with no particles -----------------------------------------------------------

def no_particles():
    C = "no_particles"

    def box(a, b):
        return {"shape": "box", "min": a, "max": b}

    def two(key, shape, words=("spacing",), dim=2):
        j = scene2d(bodies=False) if dim == 2 else scene3d()
        j[key] = [shape]
        return j, refuse(5, f"{key}[0]", *words)

    cases2 = {
        "empty_intersection_wall": ("walls", {"shape": "intersection", "shapes": [
            box([0.12, 0.02], [0.14, 0.08]), box([0.16, 0.02], [0.18, 0.08])]}),
        "empty_difference_body": ("bodies", {"shape": "difference", "shapes": [
            box([0.12, 0.02], [0.16, 0.06]), box([0.1, 0], [0.2, 0.1])]}),
        "thin_polyline_wall": ("walls", {"shape": "polyline", "points": [[0.12, 0.1], [0.18, 0.1]],
                                         "thickness": 0.005}),
        "thin_box_body": ("bodies", box([0.12, 0.095], [0.18, 0.105])),
        "thin_box_wall": ("walls", box([0.132, 0.02], [0.138, 0.18])),
        "circle_r_1e-4_body": ("bodies", {"shape": "circle", "center": [0.15, 0.1], "radius": 1e-4}),
        "circle_r_1e-4_wall": ("walls", {"shape": "circle", "center": [0.15, 0.1], "radius": 1e-4}),
        "union_of_tiny_circles_body": ("bodies", {"shape": "union", "shapes": [
            {"shape": "circle", "center": [0.15, 0.1], "radius": 1e-4},
            {"shape": "circle", "center": [0.16, 0.1], "radius": 1e-4}]}),
        "rotated_thin_box_wall": ("walls", dict(box([-0.003, -0.05], [0.003, 0.05]), rotate=45,
                                               translate=[0.15, 0.16])),
    }
    for name, (key, shape) in cases2.items():
        j, e = two(key, shape)
        cli_case(C, name, e, j, prior=name == "empty_intersection_wall")
    cases3 = {
        "cylinder_r_1e-4_body": ("bodies", {"shape": "cylinder", "base": [0.12, 0.06, 0.04],
                                            "top": [0.12, 0.06, 0.12], "radius": 1e-4}),
        "cylinder_r_1e-4_wall": ("walls", {"shape": "cylinder", "base": [0.12, 0.06, 0.04],
                                           "top": [0.12, 0.06, 0.12], "radius": 1e-4}),
        "sphere_r_1e-4_body": ("bodies", {"shape": "sphere", "center": [0.12, 0.06, 0.1],
                                          "radius": 1e-4}),
        "cone_tiny_wall": ("walls", {"shape": "cone", "base": [0.12, 0.06, 0.04],
                                     "top": [0.12, 0.06, 0.12], "base_radius": 1e-4,
                                     "top_radius": 0}),
        "empty_difference_3d_wall": ("walls", {"shape": "difference", "shapes": [
            {"shape": "sphere", "center": [0.12, 0.06, 0.1], "radius": 0.02},
            box([0.09, 0.0, 0.07], [0.16, 0.12, 0.13])]}),
    }
    for name, (key, shape) in cases3.items():
        j, e = two(key, shape, dim=3)
        cli_case(C, name, e, j)
    j = scene2d(bodies=False)
    j["fluids"].append({"material": "water", "shape": "polygon",
                        "points": [[0.101, 0.101], [0.105, 0.101], [0.101, 0.105]]})
    cli_case(C, "fluid_between_lattice_points", refuse(5, "fluids[1]"), j)
    j = scene2d(bodies=False)
    j["fluids"].append({"material": "water", "shape": "intersection", "shapes": [
        box([0.12, 0.02], [0.14, 0.08]), box([0.16, 0.02], [0.18, 0.08])]})
    cli_case(C, "fluid_empty_intersection", refuse(5, "fluids[1]"), j)
    j = scene2d(bodies=False)
    j["bodies"] = [box([0.0, 0.0], [0.12, 0.14])]
    cli_case(C, "fluid_inside_a_body", refuse(5, "fluids[0]"), j)


# ----- 7. restart --------------------------------------------------------------------------------

def restart_first_run(ctx, d, fname="body.stl", data=None, dim=3):
    """A restart case's first run, in <d>/A with checkpoints; returns A, an empty <d>/B, a checkpoint."""
    v, f = cube()
    a = os.path.join(d, "A")
    os.makedirs(a)
    if dim == 3:
        write(a, fname, data or (obj(v, f) if fname.endswith(".obj") else stl_ascii(v, f)))
        write(a, "scene.json", json.dumps(scene_mesh(fname)))
    else:
        j = scene2d(bodies=False)
        j["walls"] = [{"shape": "polygon", "points": [[0.12, 0.1], [0.18, 0.1], [0.15, 0.16]]}]
        write(a, "scene.json", json.dumps(j))
    r = run_proc(ctx, [ctx.app(dim), "scene.json", "--out", "outA", "--end-time", "0.004",
                       "--checkpoint-every", "0.002", "--quiet", "--threads", "1"], a)
    chks = sorted(x for x in os.listdir(os.path.join(a, "outA")) if x.startswith("checkpoint_")) \
        if os.path.isdir(os.path.join(a, "outA")) else []
    if r.rc != 0 or not chks:
        raise RuntimeError(f"the first run failed ({r.rc}): {r.err[-300:]}")
    b = os.path.join(d, "B")
    os.makedirs(b)
    return a, b, os.path.join(a, "outA", chks[0])


def rcase(name, expect, act, dim=3, fname="body.stl"):
    """A restart case: act(ctx, A, B, checkpoint) gives the argv, its folder and a folder to watch."""
    def fn(ctx, d):
        a, b, chk = restart_first_run(ctx, d, fname, dim=dim)
        argv, cwd, watch = act(ctx, a, b, chk)
        argv = [ctx.app(dim if "@2D" not in argv else 2)] + [x for x in argv if x != "@2D"]
        argv += ["--threads", "1", "--quiet"]
        before = checksums(watch) if watch else None
        r = run_proc(ctx, argv, cwd)
        res = classify_cli(expect, r, lost_files(before, watch) if watch else ())
        res.repro = "cd " + cwd + " && " + " ".join(shq(x) for x in argv)
        return res
    CASES.append(Case("restart", name, expect, fn))


def restart():
    _, f = cube()
    v_edit, _ = cube(side=0.121)

    rcase("checkpoint_alone_other_dir", ACCEPT,
          lambda ctx, a, b, chk: (["--restart", chk, "--out", os.path.join(b, "outB")], b, None))
    rcase("checkpoint_alone_default_out", ACCEPT,
          lambda ctx, a, b, chk: (["--restart", chk], b, None))
    rcase("checkpoint_alone_longer_end", ACCEPT,
          lambda ctx, a, b, chk: (["--restart", chk, "--out", "o", "--end-time", "0.006"], b, None))

    def moved(ctx, a, b, chk):
        shutil.copytree(a, os.path.join(b, "copy"), ignore=shutil.ignore_patterns("outA"))
        return (["copy/scene.json", "--restart", chk, "--out", "o"], b, None)
    rcase("scene_copied_with_mesh_elsewhere", ACCEPT, moved)

    def renamed(ctx, a, b, chk):
        shutil.copy(os.path.join(a, "body.stl"), os.path.join(b, "other_name.stl"))
        write(b, "scene.json", json.dumps(scene_mesh("other_name.stl")))
        return (["scene.json", "--restart", chk, "--out", "o"], b, None)
    rcase("mesh_same_content_other_name", ACCEPT, renamed)

    def edited(ctx, a, b, chk):
        write(a, "body.stl", stl_ascii(v_edit, f))
        return (["--restart", chk, "--out", os.path.join(b, "o")], b, None)
    by_file = ("body.stl", "bodies[0].file")
    rcase("mesh_edited", refuse(8, by_file), edited)

    def edited_obj(ctx, a, b, chk):
        write(a, "body.obj", obj(v_edit, f))
        return (["--restart", chk, "--out", os.path.join(b, "o")], b, None)
    rcase("mesh_edited_obj", refuse(8, ("body.obj", "bodies[0].file")), edited_obj, fname="body.obj")

    def edited_into_a(ctx, a, b, chk):
        write(a, "body.stl", stl_ascii(v_edit, f))
        return (["--restart", chk, "--out", os.path.join(a, "outA")], b, os.path.join(a, "outA"))
    rcase("mesh_edited_into_its_output", refuse(8, by_file), edited_into_a)

    def edited_scene(ctx, a, b, chk):
        write(a, "body.stl", stl_ascii(v_edit, f))
        return ([os.path.join(a, "scene.json"), "--restart", chk, "--out", "o"], b, None)
    rcase("mesh_edited_with_scene_file", refuse(8, by_file), edited_scene)

    def deleted(ctx, a, b, chk):
        os.remove(os.path.join(a, "body.stl"))
        return (["--restart", chk, "--out", "o"], b, None)
    rcase("mesh_deleted", refuse((5, 8), "body.stl"), deleted)
    restart_bad_checkpoints()


def restart_bad_checkpoints():
    """restart's cases of a bad checkpoint (cut short, corrupt, missing, not one) or changed settings."""
    def truncated(ctx, a, b, chk):
        data = open(chk, "rb").read()
        write(b, "cut.chk", data[: len(data) // 2])
        return (["--restart", "cut.chk", "--out", "o"], b, None)
    rcase("checkpoint_truncated", refuse(8, "cut.chk"), truncated)

    def corrupted(ctx, a, b, chk):
        data = bytearray(open(chk, "rb").read())
        data[len(data) // 2] ^= 0x55
        write(b, "bad.chk", bytes(data))
        return (["--restart", "bad.chk", "--out", "o"], b, None)
    rcase("checkpoint_corrupted", refuse(8, "bad.chk"), corrupted)
    rcase("checkpoint_is_a_directory", refuse(8, "outA"),
          lambda ctx, a, b, chk: (["--restart", os.path.join(a, "outA"), "--out", "o"], b, None))
    rcase("checkpoint_missing", refuse(8, "none.chk"),
          lambda ctx, a, b, chk: (["--restart", "none.chk", "--out", "o"], b, None))
    rcase("checkpoint_is_a_scene", refuse(8, "scene.json"),
          lambda ctx, a, b, chk: (["--restart", os.path.join(a, "scene.json"), "--out", "o"], b, None))
    rcase("checkpoint_3d_to_fluid_sim", refuse(8, ("dimension", "fluid_sim_3d", "3D")),
          lambda ctx, a, b, chk: (["@2D", "--restart", chk, "--out", "o"], b, None))
    rcase("restart_spacing_changed", refuse(8, "particles.spacing"),
          lambda ctx, a, b, chk: ([os.path.join(a, "scene.json"), "--restart", chk,
                                   "--set", "particles.spacing=0.05", "--out", "o"], b, None))
    rcase("restart_output_every_changed", ACCEPT,
          lambda ctx, a, b, chk: (["--restart", chk, "--set", "output.every=0.0005", "--out", "o"],
                                  b, None))
    rcase("restart_2d_checkpoint_alone", ACCEPT,
          lambda ctx, a, b, chk: (["--restart", chk, "--out", "o"], b, None), dim=2)


# ----- 8. messages and command line --------------------------------------------------------------

def cli():
    C = "cli"
    s = scene2d()
    cli_case(C, "version_bogus", refuse(2, "--bogus"), args=["--version", "--bogus"], dim=2,
             end_time=None, bare=True)
    cli_case(C, "version_with_scene", refuse(2, "--version"), s,
             args=["scene.json", "--version"], end_time=None, bare=True)
    cli_case(C, "print_scene_list_scenes", refuse(2, "--print-scene", "--list-scenes"),
             args=["--print-scene", "--list-scenes"], dim=2, end_time=None, bare=True)
    cli_case(C, "unknown_option", refuse(2, "--frobnicate"), s, args=["--frobnicate"])
    cli_case(C, "end_time_nan", refuse(2, "--end-time"), s, end_time="nan", prior=True)
    cli_case(C, "end_time_minus_1", refuse(2, "--end-time"), s, end_time="-1")
    cli_case(C, "threads_0", refuse(2, "--threads"), s, args=["--threads", "0"])
    cli_case(C, "checkpoint_every_inf", refuse(2, "--checkpoint-every"), s,
             args=["--checkpoint-every", "inf"])
    cli_case(C, "set_without_equals", refuse(2, "--set", "particles.spacing"), s,
             args=["--set", "particles.spacing"], prior=True)
    cli_case(C, "set_brackets", refuse(2, "fluids[0]"), s, args=["--set", "fluids[0].temperature=30"])
    cli_case(C, "set_1e400", refuse(2, "1e400"), s, args=["--set", "particles.spacing=1e400"])
    cli_case(C, "set_missing_element", refuse(2, "fluids.7"), s, args=["--set", "fluids.7.temperature=3"])
    cli_case(C, "other_dimension", refuse(5, "fluid_sim_3d"), scene3d(), dim=2, prior=True)
    cli_case(C, "missing_scene", refuse(3, "nothere.json"), args=["nothere.json"], dim=2)
    cli_case(C, "scene_is_directory", refuse(3, "adir"), args=["adir"], dim=2,
             setup=lambda d: os.makedirs(os.path.join(d, "adir")))
    def fifo_scene(d):  # a scene through a pipe, as `fluid_sim <(cat scene.json)` gives it
        path = os.path.join(d, "pipe.json")
        os.mkfifo(path)

        def writer():
            with open(path, "w") as fh:
                fh.write(json.dumps(s))
        threading.Thread(target=writer, daemon=True).start()
    cli_case(C, "scene_through_a_pipe", ACCEPT, args=["pipe.json"], dim=2, setup=fifo_scene)
    cli_case(C, "invalid_json", refuse(4, "scene.json:"), raw=json.dumps(s)[:-40], dim=2, prior=True)
    cli_case(C, "nested_100_levels", refuse(4, ("64", "nest")),
             raw='{"dimension": 2, "name": ' + "[" * 100 + "]" * 100 + "}", dim=2)
    cli_case(C, "scene_over_16MiB", refuse(3, ("16 MiB", "MiB")),
             raw=json.dumps(s)[:-1] + ', "description": "' + "x" * (17 << 20) + '"}', dim=2)
    cli_case(C, "misspelt_key", refuse(5, "partciles", "particles"),
             raw=json.dumps(s).replace('"particles"', '"partciles"'), dim=2, prior=True)
    cli_case(C, "out_is_a_file", refuse(7, "afile"), s, args=["--out", "@D/afile"],
             setup=lambda d: write(d, "afile", "x"))
    cli_case(C, "out_unwritable", refuse(7, "/proc/nope"), s, args=["--out", "/proc/nope/out"])
    cli_case(C, "restart_and_version", refuse(2, "--version"), args=["--version", "--restart", "x.chk"],
             dim=2, end_time=None, bare=True)
    cli_shared_folder(C)
    cli_second_thread(C)


def two_runs(ctx, d, second_python=False):
    """Two runs writing one folder at once: the second (app, or Python) must be refused."""
    j = scene2d()
    j["output"]["every"] = 0.5
    write(d, "long.json", json.dumps(j))
    out = os.path.join(d, "out")
    # Long enough to be running whatever the machine's load; stopped with Ctrl-C after.
    first = subprocess.Popen([ctx.fs2, "long.json", "--out", out, "--end-time", "60",
                              "--threads", "1", "--quiet"], cwd=d, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, env=ctx.env, start_new_session=True)
    t0 = time.time()
    while time.time() - t0 < 30 and not os.path.exists(os.path.join(out, "particles_0000.vtu")):
        time.sleep(0.05)
    early = checksums(out) if os.path.isdir(out) else {}
    if second_python:
        r = run_python(ctx, f"sim = numerics.Simulation({os.path.join(d, 'long.json')!r}, "
                            f"out={out!r}, threads=1, quiet=True)\n", d)
        res = classify_py(refuse(7, "in use", "out", excs=("RunError",)), r)
        res.repro = f"(fluid_sim long.json --out out --end-time 60 &) ; python case.py in {d}"
    else:
        argv = [ctx.fs2, "long.json", "--out", out, "--end-time", "0.01", "--threads", "1",
                "--quiet"]
        r = run_proc(ctx, argv, d)
        running = first.poll() is None
        res = classify_cli(refuse(7, "in use"), r)
        if not running and res.outcome == "clean":
            res.note = "the first run ended before the second: inconclusive"
        res.repro = (f"cd {d} && (fluid_sim long.json --out out --end-time 60 &); sleep 1; "
                     + " ".join(shq(a) for a in argv))
    if first.poll() is None:
        os.killpg(first.pid, signal.SIGINT)  # a clean stop: exit 130, summary.json written
    else:
        res.note += " the first run ended before the second began: inconclusive"
        res.outcome = "unclear"
    try:
        fo, fe = first.communicate(timeout=ctx.timeout * 3)
    except subprocess.TimeoutExpired:
        os.killpg(first.pid, signal.SIGKILL)
        return Result("hang", None, "", "the first run did not end")
    lost = [k for k, h in early.items() if k.endswith(".vtu") and checksums(out).get(k) != h]
    if first.returncode not in (0, 130) or not os.path.exists(os.path.join(out, "summary.json")) or lost:
        res.note += f" first run harmed: exit {first.returncode}, {fe.decode()[-200:]} {lost}"
        res.outcome = "data_loss"
    return res


def cli_shared_folder(C):
    """cli's cases of two runs (apps or Python) writing one folder at once."""
    CASES.append(Case(C, "two_runs_one_folder", refuse(7, "in use"), lambda ctx, d: two_runs(ctx, d)))
    CASES.append(Case(C, "python_while_app_writes_folder", refuse(7, "in use", excs=("RunError",)),
                      lambda ctx, d: two_runs(ctx, d, True)))
    py_case(C, "two_simulations_one_folder", refuse(7, "in use", excs=("RunError",)),
            "a = numerics.Simulation(SCENE, out=OUT, threads=1, quiet=True)\n"
            "b = numerics.Simulation(SCENE, out=OUT, threads=1, quiet=True)\n")


def cli_second_thread(C):
    """cli's cases of a Simulation used from a second thread while the first runs it."""
    # The first thread is held inside run() (in its callback) while the second tries, whatever
    # the machine's speed.
    thread_code = """\
sim = numerics.Simulation(SCENE, out=OUT, threads=1, quiet=True, end_time=0.6)
box = {}
inside, go = threading.Event(), threading.Event()
def hold(s):
    inside.set()
    go.wait()
def worker():
    try:
        box['rc'] = sim.run(callback=hold, every=0.01, progress=False)
    except Exception as e:
        box['err'] = repr(e)
t = threading.Thread(target=worker)
t.start()
inside.wait(30)
RES['first_running'] = t.is_alive()
try:
    %s
finally:
    go.set()
    t.join()
    RES['first'] = box
"""
    for name, stmt in [("run_from_second_thread", "sim.run(until=0.5, progress=False)"),
                       ("step_from_second_thread", "sim.step()"),
                       ("particles_from_second_thread", "sim.particles.temperature.sum()")]:
        py_case(C, name, refuse(2, "another thread", excs=("RunError",)), thread_code % stmt)


# ----- 9. scenes at the edge of sense ------------------------------------------------------------

def edge_2d(**sets):
    """scene2d() with values set by path, a__0__b=v for j["a"][0]["b"] = v."""
    j = scene2d()
    for path, val in sets.items():
        node = j
        keys = path.split("__")
        for k in keys[:-1]:
            node = node[int(k)] if k.isdigit() else node.setdefault(k, {})
        node[keys[-1]] = val
    return j


def edge_2d_auto(**sets):
    """edge_2d(**sets) with the water's sound speed "auto" (c0 = 10 U)."""
    j = edge_2d(**sets)
    j["materials"]["water"]["sound_speed"] = "auto"
    return j


def edge():
    C = "edge"
    cli_case(C, "pressure_minus_1e6", refuse(5, "fluids[0]", "pressure"),
             edge_2d(fluids__0__pressure=-1e6), prior=True)
    cli_case(C, "pressure_1e9", refuse(5, "fluids[0]", "pressure"), edge_2d(fluids__0__pressure=1e9))
    cli_case(C, "pressure_expression_minus_1e6", refuse((5, 6), "fluids[0]", "pressure"),
             edge_2d(fluids__0__pressure="-1e6*y"))
    cli_case(C, "water_at_20000C", warn("fluids[0]", "temperature"),
             edge_2d(fluids__0__temperature=20000), quiet=False, stop_after=15)
    cli_case(C, "water_at_minus_300C", refuse(5, "fluids[0]", "temperature"),
             edge_2d(fluids__0__temperature=-300))
    cli_case(C, "wall_temperature_1e5", refuse(5, "x_max", "temperature"),
             edge_2d(boundaries__x_max__thermal__temperature=1e5))
    # With the "auto" sound speed (c0 = 10 U) a fast wall or flow means a tiny step: a warning
    # about the number of steps, or a refusal above 1e6 m/s (docs/scenes.md, materials).
    cli_case(C, "wall_moving_1e5_m_s", warn("steps"), edge_2d_auto(boundaries__y_min__velocity=[1e5, 0]),
             quiet=False, stop_after=15, end_time="0.1")
    cli_case(C, "wall_moving_1e6_m_s", refuse(5, "sound_speed", "y_min"),
             edge_2d_auto(boundaries__y_min__velocity=[1e6, 0]))
    cli_case(C, "fluid_velocity_1e5", warn("steps"), edge_2d_auto(fluids__0__velocity=[1e5, 0]),
             quiet=False, stop_after=15, end_time="0.1")
    cli_case(C, "max_speed_1e5", warn("steps"), edge_2d_auto(physics__max_speed=1e5), quiet=False,
             stop_after=15, end_time="0.1")
    cli_case(C, "gravity_1e12", refuse(5, "sound_speed", "gravity"), edge_2d_auto(gravity=[0, -1e12]))
    # With a sound speed given far below the flow's speed: refused, or stopped at once (exit 9)
    # naming the sound speed (docs/scenes.md, exit code 9).
    cli_case(C, "wall_1e5_m_s_given_c_20", refuse((5, 9), "sound speed"),
             edge_2d(boundaries__y_min__velocity=[1e5, 0]))
    cli_case(C, "fluid_1e5_m_s_given_c_20", refuse((5, 9), "sound speed"),
             edge_2d(fluids__0__velocity=[1e5, 0]))
    cli_case(C, "end_1e5_s_3e8_steps", warn("steps"), edge_2d(output__every=1000), quiet=False,
             stop_after=15, end_time="1e5")
    cli_case(C, "cfl_1e-6", warn("steps"), edge_2d(time__cfl=1e-6), quiet=False, stop_after=15,
             end_time="0.02")
    cli_case(C, "dense_stiff_material", warn("steps"),
             edge_2d(materials__water__density=1e7, materials__water__sound_speed=1e6),
             quiet=False, stop_after=15, end_time="1")
    j = scene3d(emitters=True)
    j["emitters"][0]["speed"] = 1e5
    cli_case(C, "emitter_speed_1e5", refuse(5, "emitters[0]", "speed"), j)
    cli_case(C, "emitter_hot_500C", warn("emitters[0]", "temperature"),
             dict(scene3d(emitters=True), emitters=[dict(TINY_3D["emitters"][0], temperature=500)]),
             quiet=False, stop_after=15)
    cli_case(C, "spacing_1e-5_tiny_domain", refuse(5, "particles.spacing"),
             edge_2d(particles__spacing=1e-5))
    cli_case(C, "domain_1e-300", refuse(5, ("domain", "spacing")),
             edge_2d(domain__max=[1e-300, 1e-300]))
    py_case(C, "py_pressure_minus_1e6", refuse(5, "fluids[0]", "pressure", excs=("SceneError",)),
            "numerics.Simulation(SCENE, out=OUT, threads=1, quiet=True)\n",
            scene=edge_2d(fluids__0__pressure=-1e6), prior=True)


BUILDERS = {"mesh_files": mesh_files, "setup_scale": setup_scale, "python_args": python_args,
            "writable": writable, "mesh_diag": mesh_diag, "no_particles": no_particles,
            "restart": restart, "cli": cli, "edge": edge}


# ---------------------------------------------------------------------------------------------

def parse_args():
    """The command line, with the apps' paths made absolute in args.fs2 and args.fs3."""
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--bin", help="folder holding fluid_sim and fluid_sim_3d (default: build/release/apps/...)")
    ap.add_argument("--python-path", default=os.path.join(REPO, "build/release/python"),
                    help="folder holding the package numerics (default build/release/python)")
    ap.add_argument("--work", help="scratch folder (default: a new temporary folder)")
    ap.add_argument("--jobs", type=int, default=2, help="cases at a time (default 2)")
    ap.add_argument("--timeout", type=float, default=60, help="seconds per process (default 60)")
    ap.add_argument("--only", action="append", choices=CLASSES, help="run only this class (repeatable)")
    ap.add_argument("--case", action="append", help="run only cases whose name contains this")
    ap.add_argument("--list", action="store_true", help="list the cases and their expectations")
    args = ap.parse_args()
    if args.bin:
        args.fs2 = os.path.join(args.bin, "fluid_sim")
        args.fs3 = os.path.join(args.bin, "fluid_sim_3d")
    else:
        args.fs2 = os.path.join(REPO, "build/release/apps/fluid_sim/fluid_sim")
        args.fs3 = os.path.join(REPO, "build/release/apps/fluid_sim_3d/fluid_sim_3d")
    args.fs2, args.fs3 = os.path.abspath(args.fs2), os.path.abspath(args.fs3)
    args.python_path = os.path.abspath(args.python_path)
    return args


def run_cases(ctx, cases, work, jobs):
    """Runs the cases, jobs at a time, printing a line as each ends; returns [(case, Result)]."""
    lock = threading.Lock()
    results = []

    def one(c):
        d = os.path.join(work, c.cls, c.name)
        shutil.rmtree(d, ignore_errors=True)
        os.makedirs(d)
        t0 = time.time()
        try:
            res = c.fn(ctx, d)
        except Exception as e:  # the probe's own set-up failed: say so, count it as unclear
            res = Result("unclear", None, f"probe set-up failed: {e!r}")
            res.repro = d
        res.seconds = time.time() - t0
        with lock:
            rc = "-" if res.rc is None else str(res.rc)
            print(f"{c.cls:13} {c.name:40} {res.outcome:10} rc={rc:4} {res.seconds:5.1f}s "
                  f"{res.message[:100]}", flush=True)
            results.append((c, res))
        return res

    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, jobs)) as ex:
        list(ex.map(one, cases))
    return results


def report(results, work):
    """Prints the cases not clean and the table, writes results.json; returns each outcome's count."""
    order = {c: i for i, c in enumerate(CLASSES)}
    results.sort(key=lambda cr: (order[cr[0].cls], cr[0].name))
    bad = [(c, r) for c, r in results if r.outcome != "clean"]
    if bad:
        print("\n# not clean:")
        for c, r in bad:
            print(f"- {c.cls}/{c.name}: {r.outcome}, exit {r.rc}; expected {c.expect.describe()}"
                  f"{'; ' + r.note if r.note else ''}\n    {r.message[:400]}\n    repro: {r.repro}")
    with open(os.path.join(work, "results.json"), "w") as fh:
        json.dump([{"class": c.cls, "name": c.name, "expected": c.expect.describe(),
                    "outcome": r.outcome, "exit": r.rc, "message": r.message, "note": r.note,
                    "repro": r.repro, "seconds": round(r.seconds, 2)} for c, r in results], fh,
                  indent=1)
    head = ["class", "cases"] + OUTCOMES
    print("\n" + "| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    total = {o: 0 for o in OUTCOMES}
    for cls in CLASSES:
        rs = [r for c, r in results if c.cls == cls]
        if not rs:
            continue
        counts = {o: sum(r.outcome == o for r in rs) for o in OUTCOMES}
        for o in OUTCOMES:
            total[o] += counts[o]
        print(f"| {cls} | {len(rs)} | " + " | ".join(str(counts[o]) for o in OUTCOMES) + " |")
    print(f"| total | {len(results)} | " + " | ".join(str(total[o]) for o in OUTCOMES) + " |")
    return total


def main():
    args = parse_args()
    for cls in args.only or CLASSES:
        BUILDERS[cls]()
    cases = [c for c in CASES if not args.case or any(s in c.name for s in args.case)]
    if args.list:
        for c in cases:
            print(f"{c.cls:13} {c.name:42} {c.expect.describe()}")
        return 0
    for p in (args.fs2, args.fs3):
        if not os.access(p, os.X_OK):
            sys.exit(f"probe.py: {p} is not an executable (--bin)")
    args.work = os.path.abspath(args.work or tempfile.mkdtemp(prefix="hostile_probe_"))
    os.makedirs(args.work, exist_ok=True)
    ctx = Ctx(args)
    print(f"# {len(cases)} cases, work folder {args.work}, {args.jobs} at a time, "
          f"timeout {args.timeout:g} s", flush=True)
    results = run_cases(ctx, cases, args.work, args.jobs)
    total = report(results, args.work)
    print(f"\n# details: {os.path.join(args.work, 'results.json')}")
    return 1 if total["crash"] or total["hang"] or total["data_loss"] else 0


if __name__ == "__main__":
    sys.exit(main())
