#!/usr/bin/python3
"""The outputs of a short run of fluid_sim or fluid_sim_3d, opened by the tools users open them
with (label tools in ctest):

  check_outputs.py run APP SCENE OUT   run APP on SCENE into OUT (emptied first)
  check_outputs.py meshio OUT          meshio reads every VTU and the .pvd series
  check_outputs.py paraview OUT        ParaView (pvbatch) runs particles_paraview.py --screenshot;
                                       the picture's pixels show the particles, coloured by
                                       temperature
  check_outputs.py movie OUT           ffprobe decodes particles.mp4: one frame per picture, and
                                       each frame (decoded by ffmpeg) is its picture

Each check exits 0 when it passes, 1 when it fails (with the reason), and 77 (ctest's
SKIP_RETURN_CODE) with the reason when its tool is not installed (scripts/setup.sh --tests
installs them). The scenes are those of tests/tools/scenes: hot water (70 C) at low x beside
cold water (10 C) at high x, a few steps, so that nothing here depends on the flow; in 2D
also a body at 40 C above the hot water.
"""

import glob
import json
import os
import shutil
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

SKIP = 77
PREFIX = "particles"


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


def skip(reason):
    print(f"SKIP: {reason}")
    sys.exit(SKIP)


def summary(out):
    with open(os.path.join(out, "summary.json"), encoding="utf-8") as f:
        return json.load(f)


def vtu_files(out):
    files = sorted(glob.glob(os.path.join(out, f"{PREFIX}_[0-9]*.vtu")))
    check(len(files) >= 2, f"{out}: expected at least 2 VTU files, found {len(files)}")
    return files


# ---------------------------------------------------------------------------------------------
# run


def run(app, scene, out):
    shutil.rmtree(out, ignore_errors=True)
    # One thread: the runs are tiny, and results do not depend on the thread count.
    cmd = [app, scene, "--out", out, "--backend", "seq", "--quiet"]
    print(" ".join(cmd), flush=True)
    rc = subprocess.run(cmd, check=False).returncode
    check(rc == 0, f"{app} exited with {rc}")
    s = summary(out)
    check(s["status"] == "completed", f"summary.json: status {s['status']!r}")
    print(f"{out}: {s['particles']} particles ({s['fluid_particles']} fluid), "
          f"{len(vtu_files(out))} outputs")


# ---------------------------------------------------------------------------------------------
# meshio


def read_csv(path):
    """The app's CSV of the fluid particles, by id: {id: {column: value}}."""
    with open(path, encoding="utf-8") as f:
        header = f.readline().strip().split(",")
        rows = {}
        for line in f:
            values = [float(v) for v in line.strip().split(",")]
            row = dict(zip(header, values))
            rows[int(row["id"])] = row
    return header, rows


def read_vtu(meshio, path):
    try:
        return meshio.read(path)
    except Exception as e:  # meshio raises whatever its parsers meet
        raise Failure(f"meshio cannot read {path}: {type(e).__name__}: {e}") from e


def check_meshio(out):
    try:
        import meshio
        import numpy as np
    except ImportError as e:
        skip(f"meshio is not installed (Debian package python3-meshio): {e}")
    s = summary(out)
    dim = s["dimension"]
    n, n_fluid = s["particles"], s["fluid_particles"]
    files = vtu_files(out)
    for path in files:
        check_meshio_vtu(meshio, np, path, dim, n, n_fluid)
    check_meshio_series(meshio, np, out, files, s)


def check_meshio_vtu(meshio, np, path, dim, n, n_fluid):
    """One VTU as meshio reads it (points, cells, fields), and its fluid as the CSV has it."""
    vector_fields = ["velocity"]
    scalar_fields = ["density", "pressure", "temperature", "mass", "material", "kind", "id"]
    name = os.path.basename(path)
    mesh = read_vtu(meshio, path)
    pts = mesh.points
    check(pts.shape == (n, 3), f"{name}: points {pts.shape}, expected ({n}, 3)")
    check(np.all(np.isfinite(pts)), f"{name}: non-finite positions")
    if dim == 2:
        check(np.all(pts[:, 2] == 0), f"{name}: 2D run with z != 0")
    else:
        check(np.ptp(pts[:, 2]) > 0, f"{name}: 3D run with all z equal")
    cells = sum(len(c.data) for c in mesh.cells)
    check(cells == n, f"{name}: {cells} cells (vertices), expected {n}")
    data = mesh.point_data
    for f in vector_fields + scalar_fields:
        check(f in data, f"{name}: no point data {f!r} (has {sorted(data)})")
        check(len(data[f]) == n, f"{name}: {f} has {len(data[f])} values, expected {n}")
        check(np.all(np.isfinite(data[f])), f"{name}: non-finite {f}")
    v = data["velocity"]
    check(v.ndim == 2 and v.shape[1] in (dim, 3),
          f"{name}: velocity of shape {v.shape} in a {dim}D run")
    if dim == 2 and v.shape[1] == 3:
        check(np.all(v[:, 2] == 0), f"{name}: 2D run with a z velocity")
    kind = data["kind"].ravel()
    check(set(np.unique(kind)) <= {0, 1, 2}, f"{name}: kinds {np.unique(kind)}")
    check(np.count_nonzero(kind == 0) == n_fluid,
          f"{name}: {np.count_nonzero(kind == 0)} fluid particles, expected {n_fluid}")
    ids = data["id"].ravel().astype(np.int64)
    check(len(np.unique(ids)) == n, f"{name}: ids are not unique")
    check(np.all(data["density"] > 0), f"{name}: density <= 0")
    fluid_t = data["temperature"].ravel()[kind == 0]
    check(fluid_t.min() < 40 < fluid_t.max(),
          f"{name}: fluid temperatures {fluid_t.min()}..{fluid_t.max()}, expected hot and cold")
    # The same values as the app's CSV of the same output, particle by particle.
    header, rows = read_csv(os.path.splitext(path)[0] + ".csv")
    check(len(rows) == n_fluid, f"{name}: the CSV has {len(rows)} rows, expected {n_fluid}")
    axes = "xyz"[:dim]
    for i in np.flatnonzero(kind == 0):
        row = rows.get(int(ids[i]))
        check(row is not None, f"{name}: fluid particle id {ids[i]} is not in the CSV")
        got = list(pts[i, :dim]) + list(v[i, :dim]) + [
            data[f].ravel()[i] for f in ("density", "pressure", "temperature")]
        want = [row[a] for a in axes] + [row["v" + a] for a in axes] + [
            row[f] for f in ("density", "pressure", "temperature")]
        check(np.allclose(got, want, rtol=1e-6, atol=1e-9),
              f"{name}: particle id {ids[i]}: meshio {got}, CSV {want}")
    print(f"{name}: {n} points, {n_fluid} fluid, fields {sorted(data)}")


def check_meshio_series(meshio, np, out, files, s):
    """The .pvd series: every VTU once, in order, at increasing times."""
    pvd = os.path.join(out, f"{PREFIX}.pvd")
    root = ET.parse(pvd).getroot()
    check(root.get("type") == "Collection", f"{pvd}: type {root.get('type')!r}")
    sets = root.findall("./Collection/DataSet")
    names = [d.get("file") for d in sets]
    times = [float(d.get("timestep")) for d in sets]
    check(names == [os.path.basename(f) for f in files],
          f"{pvd}: files {names}, the directory has {[os.path.basename(f) for f in files]}")
    check(all(a < b for a, b in zip(times, times[1:])), f"{pvd}: times not increasing: {times}")
    check(abs(times[-1] - s["final_time"]) <= 1e-9 * max(1.0, s["final_time"]),
          f"{pvd}: last time {times[-1]}, summary.json final_time {s['final_time']}")
    for name, t in zip(names, times):
        mesh = read_vtu(meshio, os.path.join(out, name))
        check("TimeValue" in mesh.field_data, f"{name}: no field data TimeValue")
        tv = float(np.ravel(mesh.field_data["TimeValue"])[0])
        check(abs(tv - t) <= 1e-9 * max(1.0, abs(t)), f"{name}: TimeValue {tv}, the .pvd says {t}")
    print(f"{os.path.basename(pvd)}: {len(sets)} files, t = {times[0]} .. {times[-1]} s")


# ---------------------------------------------------------------------------------------------
# ParaView


def pvbatch_command():
    pvbatch = shutil.which("pvbatch")
    if pvbatch is None:
        skip("pvbatch is not installed (Debian package paraview)")
    if shutil.which("pvpython") is None:  # ParaView's Python modules, which pvbatch needs
        skip("ParaView's Python is not installed (Debian package python3-paraview)")
    return [pvbatch, "--force-offscreen-rendering", f"{PREFIX}_paraview.py", "--screenshot"]


class VirtualDisplay:
    """An Xvfb server of our own for the time of a with block (Debian's ParaView renders through
    X, GLX, even off screen). -displayfd: Xvfb picks a free display and writes its number once it
    accepts clients (no waiting for a fixed time); -noreset: it stays up when pvbatch closes its
    first connection and opens the next (a server reset between them fails the second)."""

    def __enter__(self):
        xvfb = shutil.which("Xvfb")
        if xvfb is None:
            skip("Xvfb is not installed (Debian package xvfb) and there is no DISPLAY")
        r, w = os.pipe()
        self.log = tempfile.TemporaryFile()
        self.server = subprocess.Popen(
            [xvfb, "-displayfd", str(w), "-screen", "0", "1280x1024x24", "-noreset", "-nolisten",
             "tcp"], pass_fds=(w,), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
            stderr=self.log)
        os.close(w)
        with os.fdopen(r, "rb") as f:
            number = f.readline().strip()
        if not number:
            self.server.wait()
            self.log.seek(0)
            raise Failure(f"Xvfb did not start: {self.log.read().decode(errors='replace')}")
        self.display = ":" + number.decode()
        return self

    def __exit__(self, *exc):
        self.server.terminate()
        try:
            self.server.wait(timeout=30)
        except subprocess.TimeoutExpired:
            self.server.kill()
            self.server.wait()
        self.log.close()
        return False


def run_pvbatch(out, cmd, env):
    # A hang guard below ctest's TIMEOUT (600 s), so that Xvfb is stopped after a hung pvbatch:
    # about 15 s on 2 busy cores.
    try:
        return subprocess.run(cmd, cwd=out, env=env, capture_output=True, text=True,
                              check=False, timeout=400)
    except subprocess.TimeoutExpired as e:
        raise Failure(f"pvbatch hung (killed after {e.timeout} s)") from e


def render(out, cmd):
    """Runs cmd on a display of its own (Xvfb), or, without Xvfb, on the session's display."""
    # pvbatch starts as a one-process MPI program: Open MPI wants a launcher agent (ssh or rsh)
    # on the PATH even then; one that is never called will do where neither is installed.
    env = dict(os.environ)
    env.setdefault("OMPI_MCA_plm_rsh_agent", "false")
    if shutil.which("Xvfb") is None and env.get("DISPLAY"):
        return run_pvbatch(out, cmd, env)
    with VirtualDisplay() as x:
        print(f"DISPLAY={x.display} (Xvfb)")
        env["DISPLAY"] = x.display
        return run_pvbatch(out, cmd, env)


def load_png(path):
    import numpy as np
    from PIL import Image
    return np.asarray(Image.open(path).convert("RGB")).astype(int)


def paraview_picture(out):
    """Has pvbatch run particles_paraview.py --screenshot in out; the path of the picture."""
    cmd = pvbatch_command()
    picture = os.path.join(out, f"{PREFIX}_paraview.png")
    if os.path.exists(picture):
        os.remove(picture)
    print(" ".join(cmd), flush=True)
    r = render(out, cmd)
    print(r.stdout + r.stderr)
    check(r.returncode == 0, f"pvbatch exited with {r.returncode}")
    check(os.path.exists(picture), f"pvbatch wrote no {picture}")
    return picture


def check_paraview(out):
    try:
        import numpy as np
        from PIL import Image  # noqa: F401
    except ImportError as e:
        skip(f"numpy or PIL is not installed (python3-numpy, python3-pil): {e}")
    picture = paraview_picture(out)
    img = load_png(picture)
    h, w, _ = img.shape
    check((w, h) == (1280, 720), f"{picture}: {w}x{h}, expected 1280x720")
    dim = summary(out)["dimension"]

    # The background: the commonest colour of the picture's border (the box is framed with a
    # margin, and walls are hidden).
    border = np.concatenate([img[0], img[-1], img[:, 0], img[:, -1]])
    colours, counts = np.unique(border, axis=0, return_counts=True)
    background = colours[np.argmax(counts)]
    distance = np.abs(img - background).sum(axis=2)
    particle = distance > 60
    red, blue = img[..., 0], img[..., 2]
    warm = particle & (red > blue + 50)  # "Cool to Warm": 70 C is red
    cool = particle & (blue > red + 50)  # 10 C is blue
    # Leave out the colour bar with its labels (upper right corner, over the box in 2D) and the
    # orientation axes (lower left corner).
    region = np.ones((h, w), dtype=bool)
    region[: int(0.6 * h), int(0.6 * w):] = False
    region[int(0.8 * h):, : int(0.15 * w)] = False
    area = np.count_nonzero(region)
    frac = lambda m: np.count_nonzero(m & region) / area  # noqa: E731
    print(f"{picture}: {w}x{h}, background {tuple(background)}, particles {frac(particle):.1%}, "
          f"warm {frac(warm):.1%}, cool {frac(cool):.1%} of the picture")
    least = 0.15 if dim == 2 else 0.05
    check(frac(particle) >= least,
          f"{picture}: particles cover {frac(particle):.1%} of the picture, "
          f"expected >= {least:.0%}")
    check(frac(warm) >= least / 3, f"{picture}: hot water covers {frac(warm):.1%}")
    check(frac(cool) >= least / 3, f"{picture}: cold water covers {frac(cool):.1%}")
    # Hot water at low x, cold at high x: in both views low x is on the left.
    xs = np.arange(w)[None, :].repeat(h, axis=0)
    warm_x, cool_x = xs[warm & region].mean(), xs[cool & region].mean()
    print(f"mean column: hot {warm_x:.0f}, cold {cool_x:.0f}")
    check(warm_x + 0.05 * w < cool_x,
          f"{picture}: hot water (mean column {warm_x:.0f}) is not left of the cold "
          f"({cool_x:.0f})")
    if dim == 2:
        # The body at 40 C, the middle of the colour range: light grey, above the hot water.
        neutral = particle & (np.abs(red - blue) < 40) & (img.min(axis=2) > 150)
        upper_left = (xs < w // 2) & (np.arange(h)[:, None] < h // 2)
        print(f"body (light grey, upper left): {frac(neutral & upper_left):.2%} of the picture")
        check(frac(neutral & upper_left) >= 0.001,
              f"{picture}: the body at 40 C covers {frac(neutral & upper_left):.2%}")
        # Side by side: the left half hot, the right half cold.
        left, right = xs < w // 2, xs >= w // 2
        hot_left = np.count_nonzero(warm & region & left) / np.count_nonzero(warm & region)
        cold_right = np.count_nonzero(cool & region & right) / np.count_nonzero(cool & region)
        check(hot_left > 0.9 and cold_right > 0.9,
              f"{picture}: {hot_left:.0%} of the hot pixels left, {cold_right:.0%} of the cold "
              "right, expected > 90 %")


# ---------------------------------------------------------------------------------------------
# ffprobe


def check_movie(out):
    ffprobe = shutil.which("ffprobe")
    if ffprobe is None:
        skip("ffprobe is not installed (Debian package ffmpeg)")
    s = summary(out)
    movie = os.path.join(out, f"{PREFIX}.mp4")
    check(os.path.exists(movie), f"no {movie} (summary.json video_note: {s.get('video_note')!r})")
    check(os.path.basename(s["video"]) == os.path.basename(movie),
          f"summary.json video {s['video']!r}, expected {movie}")
    pictures = sorted(glob.glob(os.path.join(out, f"{PREFIX}_[0-9]*.png")))
    cmd = [ffprobe, "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
           "stream=codec_name,width,height,nb_read_frames", "-of", "json", movie]
    r = subprocess.run(cmd, capture_output=True, text=True, check=False)
    check(r.returncode == 0, f"ffprobe exited with {r.returncode}: {r.stderr.strip()}")
    streams = json.loads(r.stdout).get("streams", [])
    check(len(streams) == 1, f"{movie}: {len(streams)} video streams")
    st = streams[0]
    frames = int(st["nb_read_frames"])
    print(f"{movie}: {st['codec_name']} {st['width']}x{st['height']}, {frames} frames decoded, "
          f"{len(pictures)} pictures")
    check(st["codec_name"] == "h264", f"{movie}: codec {st['codec_name']}, expected h264")
    check(frames == len(pictures), f"{movie}: {frames} frames, the run wrote {len(pictures)} "
          "pictures")
    check(len(pictures) == len(vtu_files(out)),
          f"{len(pictures)} pictures for {len(vtu_files(out))} outputs")
    # The frames are the pictures, in order: each decoded frame (H.264 is lossy, and the frame
    # is padded to even sizes) close to its picture.
    try:
        import numpy as np
        from PIL import Image
    except ImportError:
        print("numpy or PIL not installed: the frames are not compared with the pictures")
        return
    ffmpeg = shutil.which("ffmpeg")
    check(ffmpeg is not None, "ffprobe without ffmpeg")
    width, height = int(st["width"]), int(st["height"])
    first = Image.open(pictures[0])
    check((width, height) == (first.width + first.width % 2, first.height + first.height % 2),
          f"{movie}: {width}x{height}, the pictures {first.width}x{first.height}")
    r = subprocess.run([ffmpeg, "-v", "error", "-nostdin", "-i", movie, "-f", "rawvideo",
                        "-pix_fmt", "rgb24", "-"], capture_output=True, check=False)
    check(r.returncode == 0, f"ffmpeg could not decode {movie}: {r.stderr.decode().strip()}")
    frames = np.frombuffer(r.stdout, dtype=np.uint8).reshape(-1, height, width, 3).astype(int)
    check(len(frames) == len(pictures), f"{movie}: ffmpeg decoded {len(frames)} frames")
    for i, path in enumerate(pictures):
        picture = load_png(path)
        ph, pw, _ = picture.shape
        diff = np.abs(frames[i, :ph, :pw] - picture).mean()
        print(f"frame {i}: mean difference {diff:.2f} / 255 from {os.path.basename(path)}")
        check(diff < 6, f"{movie}: frame {i} differs from {os.path.basename(path)} by {diff:.1f}")


def main(argv):
    try:
        if len(argv) == 5 and argv[1] == "run":
            run(argv[2], argv[3], argv[4])
        elif len(argv) == 3 and argv[1] == "meshio":
            check_meshio(argv[2])
        elif len(argv) == 3 and argv[1] == "paraview":
            check_paraview(argv[2])
        elif len(argv) == 3 and argv[1] == "movie":
            check_movie(argv[2])
        else:
            print(__doc__, file=sys.stderr)
            return 2
    except Failure as e:
        print(f"FAIL: {e}", file=sys.stderr)
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
