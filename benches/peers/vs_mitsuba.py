#!/usr/bin/env python3
"""lobe's batched GGX conductor against Mitsuba 3's JIT, on the same directions, one core.

    python3 benches/peers/vs_mitsuba.py [N]        # N lanes, default 2^20

What it needs (CI does not set it up; the script says so and exits 2 without it):
  * Python 3 with the `mitsuba` (3.x) and `numpy` packages from PyPI:
        python3 -m pip install mitsuba numpy
  * an LLVM shared library for Dr.Jit's `llvm_ad_rgb` variant, e.g. Debian's `libllvm19`:
        apt-get install libllvm19        (Dr.Jit finds libLLVM.so.*; or set DRJIT_LIBLLVM_PATH)
  * cargo, to build `batch-timing` (benches/peers/batch_timing.rs).

The model on both sides: GGX, alpha 0.3, gold (lobe's RGB complex index; Mitsuba's `Au`
spectral data converted to RGB by Mitsuba), visible-normal sampling without the bounded cap
(Mitsuba's `sample_visible = true`). Mitsuba's `eval` includes the cosine factor and its
`sample` returns the weight; lobe's `eval` is f and its `sample` returns f and pdf: each side
does the work its API asks for.

Timing: Dr.Jit on one thread (`dr.set_thread_count(1)`), each kernel compiled by a first
call (not timed), then five timed launches; lobe's batched calls (rustc's IEEE arithmetic,
no contraction or reassociation; no warm-up other than one untimed pass) in `batch-timing`,
also five passes. Whether Dr.Jit approximates divisions or square roots is not assumed: the
two chain rows measure it. The two sides alternate in rounds (lobe, Mitsuba, lobe, Mitsuba,
...) and the table gives medians over rounds with their spread, and the median of the
per-round ratios.

Stores: Dr.Jit (1.5) marks its kernels' loads and stores `!nontemporal`; a streaming store
writes an output line without reading it first, an ordinary store (lobe's) reads it for
ownership. Past the L2 (2^20 lanes) that makes lobe's memory pass about 1.2-1.4x Mitsuba's; the
model calls hide it behind their arithmetic, and in a batch that stays in the L2 the streaming
store is the slower one (docs/benchmarks.md, the memory-pass paragraph). The script reads the IR
of an `a + b` kernel, the memory pass's form, and prints which kind of store it has, so
docs/benchmarks.md's explanation of the memory-pass row is checked again in every run.

Cost per call: after the table the script times Mitsuba's calls on 16 lanes, where the cost of a
call (tracing, finding the kernel, launching it) is nearly all of it; that cost is what makes
Mitsuba slower per lane at small batches (docs/benchmarks.md, the batch-size table).
"""

import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

ROUNDS = 5
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))


def fail(msg):
    print(f"vs_mitsuba.py: {msg}", file=sys.stderr)
    sys.exit(2)


try:
    import numpy as np
except ImportError:
    fail("numpy is missing: python3 -m pip install numpy")
try:
    import drjit as dr
    import mitsuba as mi
except ImportError:
    fail("Mitsuba 3 is missing: python3 -m pip install mitsuba")
try:
    mi.set_variant("llvm_ad_rgb")
except Exception as e:  # noqa: BLE001 - any failure here means no LLVM backend
    fail(
        "Mitsuba's llvm_ad_rgb variant could not start (it needs an LLVM shared library, "
        f"e.g. apt-get install libllvm19, or DRJIT_LIBLLVM_PATH): {e}"
    )


def build_lobe():
    cmd = ["cargo", "build", "--release", "-q", "-p", "lobe-peers", "--bin", "batch-timing"]
    r = subprocess.run(cmd, cwd=ROOT)
    if r.returncode != 0:
        fail("cargo build of batch-timing failed")
    return os.path.join(ROOT, "target", "release", "batch-timing")


def time_lobe(exe, path):
    out = subprocess.run([exe, "time", path], capture_output=True, text=True, check=True)
    return json.loads(out.stdout)


def load(path):
    a = np.fromfile(path, dtype="<f4")
    return a.reshape(9, -1)


def median_launch(fn, n):
    """Compile with one call, then the median of five timed launches, ns per lane."""
    dr.eval(fn())
    dr.sync_thread()
    ts = []
    for _ in range(5):
        t = time.perf_counter()
        dr.eval(fn())
        dr.sync_thread()
        ts.append((time.perf_counter() - t) * 1e9 / n)
    return statistics.median(ts)


def time_mitsuba(c):
    n = c.shape[1]
    bsdf = mi.load_dict(
        {
            "type": "roughconductor",
            "distribution": "ggx",
            "alpha": 0.3,
            "material": "Au",
            "sample_visible": True,
        }
    )
    # Mitsuba's si.wi is lobe's wo (toward the viewer); its `wo` argument is lobe's wi.
    wo = mi.Vector3f(mi.Float(c[0]), mi.Float(c[1]), mi.Float(c[2]))
    wi = mi.Vector3f(mi.Float(c[3]), mi.Float(c[4]), mi.Float(c[5]))
    u = mi.Point2f(mi.Float(c[6]), mi.Float(c[7]))
    uc = mi.Float(c[8])
    dr.eval(wo, wi, u, uc)
    si = dr.zeros(mi.SurfaceInteraction3f, n)
    si.wi = wo
    si.sh_frame = mi.Frame3f(mi.Vector3f(0, 0, 1))
    ctx = mi.BSDFContext()

    def sample():
        bs, w = bsdf.sample(ctx, si, uc, u)
        return bs.wo, bs.pdf, w

    def copy():
        return wo + wi

    # The parts batch-timing also times: the exact conductor term alone (lobe's gold, RGB,
    # one complex index per channel as Mitsuba's RGB variant holds it, at cos = wo.z), and
    # chains of twelve divisions and of twelve square roots, which show whether the JIT
    # divides and takes roots exactly (at the exact instructions' throughput) or by
    # approximations.
    gold = [(0.143, 3.983), (0.375, 2.386), (1.442, 1.603)]

    def fresnel():
        return [
            mi.fresnel_conductor(wo.z, dr.llvm.ad.Complex2f(dr.opaque(mi.Float, e), dr.opaque(mi.Float, k)))
            for e, k in gold
        ]

    x, y = 1.0 + wo.z, 1.0 + wi.z
    dr.eval(x, y)

    def divide():
        z = x
        for _ in range(12):
            z = y / z + 1.0
        return z

    def root():
        z = x
        for _ in range(12):
            z = dr.sqrt(z + y)
        return z

    return {
        "fresnel": median_launch(fresnel, n),
        "divide": median_launch(divide, n) / 12,
        "root": median_launch(root, n) / 12,
        "eval": median_launch(lambda: bsdf.eval(ctx, si, wi), n),
        "pdf": median_launch(lambda: bsdf.pdf(ctx, si, wi), n),
        "sample": median_launch(sample, n),
        "copy": median_launch(copy, n),
    }


def drjit_store_kind():
    """The kind of store in the LLVM IR of an `a + b` kernel, the memory pass's form.

    Dr.Jit's Python module prints the IR to Python's standard output (to the C library's
    standard error when it cannot), so both file descriptors go to a file for the one launch,
    and are restored, flushed first, whatever happens.
    """
    if not hasattr(dr.JitFlag, "PrintIR"):
        return "unknown (this Dr.Jit has no PrintIR flag)"
    a = dr.opaque(mi.Float, 1.0, 1024)
    b = dr.opaque(mi.Float, 2.0, 1024)
    dr.eval(a, b)
    with tempfile.TemporaryFile(mode="w+") as log:
        sys.stdout.flush()
        sys.stderr.flush()
        saved = [os.dup(fd) for fd in (1, 2)]
        for fd in (1, 2):
            os.dup2(log.fileno(), fd)
        try:
            dr.set_flag(dr.JitFlag.PrintIR, True)
            dr.eval(a + b)
            dr.sync_thread()
        finally:
            try:
                dr.set_flag(dr.JitFlag.PrintIR, False)
            finally:
                sys.stdout.flush()
                sys.stderr.flush()
                for fd, old in zip((1, 2), saved):
                    os.dup2(old, fd)
                    os.close(old)
        log.seek(0)
        stores = [line for line in log if line.lstrip().startswith("store <")]
    streaming = sum("!nontemporal" in line for line in stores)
    if not stores:
        return "not found in the IR"
    if streaming == len(stores):
        return "nontemporal (streaming)"
    return "ordinary" if streaming == 0 else f"mixed ({streaming} of {len(stores)} streaming)"


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 1 << 20
    dr.set_thread_count(1)
    exe = build_lobe()
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "inputs.bin")
        subprocess.run([exe, "write", path, str(n)], check=True)
        c = load(path)
        rounds = []
        for _ in range(ROUNDS):
            rounds.append((time_lobe(exe, path), time_mitsuba(c)))
    print(f"\nGGX gold conductor, alpha 0.3, {n} lanes, one core, {ROUNDS} interleaved rounds")
    print(f"lobe's batched path: {rounds[0][0]['isa']} (lobe::batch::instruction_set)")
    print("ns per lane: median [min, max] over rounds; ratio = median of per-round lobe/Mitsuba\n")
    print("| kernel (ns per lane) | lobe batched | Mitsuba 3 (llvm_ad_rgb) | ratio |")
    print("| --- | --- | --- | --- |")
    names = {
        "copy": "memory pass (wo + wi)",
        "fresnel": "conductor Fresnel alone (RGB)",
        "divide": "one division (of a chain of 12)",
        "root": "one square root (of a chain of 12)",
    }
    for k in ["eval", "pdf", "sample", "copy", "fresnel", "divide", "root"]:
        lo = [r[0][k] for r in rounds]
        mi_ = [r[1][k] for r in rounds]
        ra = [a / b for a, b in zip(lo, mi_)]
        fmt = lambda xs: f"{statistics.median(xs):.2f} [{min(xs):.2f}, {max(xs):.2f}]"  # noqa: E731
        name = names.get(k, k)
        print(f"| {name} | {fmt(lo)} | {fmt(mi_)} | {statistics.median(ra):.2f}× [{min(ra):.2f}, {max(ra):.2f}] |")
    # Mitsuba's cost per call: called from Python, each call traces the computation again,
    # finds the compiled kernel and launches it, whatever the batch.
    few = 16
    try:
        small = time_mitsuba(c[:, :few])
        per_call = ", ".join(f"{k} {small[k] * few / 1000:.1f} µs" for k in ["eval", "pdf", "sample"])
    except Exception as e:  # noqa: BLE001 - the table is printed; this line only explains it
        per_call = f"unknown ({e})"
    print(f"\nMitsuba's time per call on {few} lanes (its cost per call): {per_call}")
    try:
        kind = drjit_store_kind()
    except Exception as e:  # noqa: BLE001 - the table is printed; this line only explains it
        kind = f"unknown ({e})"
    print(f"\nDr.Jit's stores: {kind}; lobe's: ordinary")


if __name__ == "__main__":
    main()
