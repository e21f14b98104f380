"""Runs the conduction benchmark in vofdem (-physics energy) and OpenFOAM v1912 laplacianFoam (see heat-vs-openfoam).

The case: a stationary Gaussian spot (P 400 W, 1/e^2 radius R 1 mm, absorptivity 0.5, on from t = 0) at the centre
of the top of a plate [-W R, W R]^2 x [-D R, 0] (W --half-width, D --depth), conduction only, constant properties (rho 8000 kg/m^3, cp 500
J/(kg K), k 20 W/(m K): a = 5e-6 m^2/s), no latent heat (vofdem: -energy_metal_latent_heat 0 and solidus/liquidus
at 1e5/2e5 K, far above the temperatures reached), no radiation or convection, adiabatic sides and bottom, T0 300 K.
The same uniform grid of cubes h = R / --cells-per-radius in both codes, the same dt and end time (default
R^2/(2a) = 0.1 s at dt 1e-3 s, default plate half width 5 R: its adiabatic edges then add at most 0.002 K to the top layer;
at 4 R and 0.2 s they added 2.9 K at the edges, more than the codes' errors), the same implicit scheme (default BDF2 with a backward-Euler first step: vofdem's bdf2,
OpenFOAM's backward; --scheme euler: both backward Euler).
The beam: vofdem deposits each column's exact power (erf differences over its footprint) into the column's top cell;
OpenFOAM's top patch is a fixedGradient with a nonuniform List of q_f / k, q_f the same exact integral over the face
divided by its area (foam_heat.py). Both put eta P_f into the top cell under each face: the same discrete problem.
Timing: each code's own clock over the same window of steps, from step --warmup to the last multiple of --warmup
before the final step (the final step writes the field): vofdem the wall_time_s of its monitor rows (every
--warmup steps), OpenFOAM the differences of its ExecutionTime lines (its wall-clock stamps are printed too).
Microseconds per cell-step, on 1 and 2 ranks (mpiexec --bind-to core; both split in halves along x), interleaved:
each repeat runs vofdem, OpenFOAM GAMG and OpenFOAM PCG + DIC back to back; medians, spread (max - min) / median,
and the median of the per-repeat ratios OpenFOAM / vofdem with OpenFOAM's faster solver (by median).
The load: the machine's CPU use during each run that was not the run's own (/proc/stat less the run's CPU time).
Accuracy: each code's final field on the top layer's cell centres (depth h/2) against the semi-infinite solution of
a Gaussian surface flux (Eagar and Tsai with V = 0; test/energy/test_moving_source.py has the moving form):
  T - T0 = eta P/(pi rho cp sqrt(4 pi a)) int_0^t tau^-1/2 /(2 a tau + s^2) exp(-r^2/(4 a tau + 2 s^2) - z^2/(4 a tau)) dtau,
s = R/2; max |error| over the top layer, RMS over its cells within r <= 2 R, the error at the cell next to the spot
centre; the nearest image sources (the finite plate's adiabatic faces) are evaluated to show they do not matter.
"""
import argparse
import datetime
import math
import os
import re
import resource
import statistics
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import foam_heat as fh  # noqa: E402
import record  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
BUILD = os.environ.get("VOFDEM_BUILD", os.path.join(ROOT, "build"))
WORK = os.path.join(BUILD, "bench", "heat-vs-openfoam")
RESULTS = os.path.join(ROOT, "results", "bench-heat-vs-openfoam.md")
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="1")
RHO, CP, K, ETA, P, R, T0 = 8000.0, 500.0, 20.0, 0.5, 400.0, 1e-3, 300.0
A = K / (RHO * CP)
SIG = R / 2
OUT = []


def say(s=""):
    print(s, flush=True)
    OUT.append(s)


def mpi(n):
    # pml ob1 as in vof_vs_openfoam.py (Debian's Open MPI otherwise probes its network layers at start-up)
    return ["mpiexec", "--mca", "pml", "ob1", "-n", str(n), "--bind-to", "core", "--map-by", "core"]


def vofdem_binary(given):
    for p in ([given] if given else []) + [os.environ.get("VOFDEM_BIN", ""), os.path.join(BUILD, "src", "vofdem"), os.path.join(BUILD, "vofdem")]:
        if p and os.access(p, os.X_OK):
            return p
    return None


# ---------------------------------------------------------------- the load on the machine


def cpu_jiffies():
    """(busy, total) jiffies of all CPUs from /proc/stat."""
    v = [int(x) for x in open("/proc/stat").readline().split()[1:]]
    idle = v[3] + v[4]
    return sum(v) - idle, sum(v)


def own_cpu():
    c, s = resource.getrusage(resource.RUSAGE_CHILDREN), resource.getrusage(resource.RUSAGE_SELF)
    return c.ru_utime + c.ru_stime + s.ru_utime + s.ru_stime


class Meter:
    """The CPU (in cores) used on the machine during a run by anything but this script and its children."""

    def __enter__(self):
        self.b0, self.t0 = cpu_jiffies()
        self.c0, self.w0 = own_cpu(), time.monotonic()
        return self

    def __exit__(self, *exc):
        b1, t1 = cpu_jiffies()
        hz = os.sysconf("SC_CLK_TCK")
        wall = time.monotonic() - self.w0
        self.foreign = max(0.0, ((b1 - self.b0) / hz - (own_cpu() - self.c0)) / wall) if wall > 0 else 0.0
        return False


def children(pid):
    out = []
    for d in os.listdir("/proc"):
        if d.isdigit():
            try:
                st = open("/proc/%s/stat" % d).read()
            except OSError:
                continue
            if int(st[st.rindex(")") + 2:].split()[1]) == pid:
                out.append(int(d))
    return out


def rank_zero(pid):
    """The process of MPI rank 0 below mpiexec's pid (stdbuf execs mpiexec in place), or None."""
    todo = [pid]
    while todo:
        q = todo.pop()
        try:
            env = open("/proc/%d/environ" % q, "rb").read().split(b"\0")
        except OSError:
            env = []
        if b"OMPI_COMM_WORLD_RANK=0" in env:
            return q
        todo += children(q)
    return None


def proc_cpu(pid):
    """utime + stime of a process, in seconds (None once it is gone)."""
    try:
        st = open("/proc/%d/stat" % pid).read()
    except OSError:
        return None
    f = st[st.rindex(")") + 2:].split()
    return (int(f[11]) + int(f[12])) / os.sysconf("SC_CLK_TCK")


# ---------------------------------------------------------------- the analytic solution


def exact(x, y, z, t, nodes=None):
    """T at the points (x, y, z) (arrays, z <= 0 below the top at 0) at time t, the spot at (0, 0):
    tau = u^2 removes tau^-1/2; composite Gauss-Legendre in u on [0, sqrt(t)]."""
    if nodes is None:
        nodes = quadrature(t, 256)
    u, w = nodes
    r2 = (np.asarray(x) ** 2 + np.asarray(y) ** 2)[..., None]
    zz = (np.asarray(z) ** 2)[..., None]
    u2 = u * u
    f = 2.0 / (2 * A * u2 + SIG * SIG) * np.exp(-r2 / (4 * A * u2 + 2 * SIG * SIG) - zz / (4 * A * u2))
    return T0 + ETA * P / (math.pi * RHO * CP * math.sqrt(4 * math.pi * A)) * (f * w).sum(axis=-1)


def quadrature(t, panels, order=16):
    g, gw = np.polynomial.legendre.leggauss(order)
    edges = np.linspace(0.0, math.sqrt(t), panels + 1)
    u = ((edges[:-1, None] + edges[1:, None]) / 2 + (edges[1:, None] - edges[:-1, None]) / 2 * g[None, :]).ravel()
    w = ((edges[1:, None] - edges[:-1, None]) / 2 * gw[None, :]).ravel()
    return u, w


# ---------------------------------------------------------------- the case


class Case:
    def __init__(self, a):
        self.m = a.cells_per_radius
        self.h = R / self.m
        self.cells = (2 * a.half_width * self.m, 2 * a.half_width * self.m, a.depth * self.m)
        self.lo = (-a.half_width * R, -a.half_width * R, -a.depth * R)
        self.hi = (a.half_width * R, a.half_width * R, 0.0)
        self.n = self.cells[0] * self.cells[1] * self.cells[2]
        self.dt = a.dt
        self.steps = int(round(a.end_time / a.dt))
        if abs(self.steps * a.dt - a.end_time) > 1e-9 * a.end_time:
            sys.exit("heat-vs-openfoam: --end-time must be a multiple of --dt")
        self.t_end = self.steps * a.dt
        self.scheme = a.scheme
        self.w = a.warmup
        self.last = ((self.steps - 1) // self.w) * self.w  # the last timed step: a monitor row before the final step
        if self.last <= self.w:
            sys.exit("heat-vs-openfoam: need more than 2 --warmup steps in the run (%d steps)" % self.steps)
        self.timed = self.last - self.w
        self.xc = self.lo[0] + (np.arange(self.cells[0]) + 0.5) * self.h
        self.yc = self.lo[1] + (np.arange(self.cells[1]) + 0.5) * self.h


def run_vofdem(exe, c, ranks, outdir, extra):
    """One vofdem run: (us per cell-step, linear iterations per step, enthalpy iterations per step, final top layer,
    log_view path, foreign load)."""
    if exe is None:
        raise RuntimeError("no vofdem binary (give --vofdem or VOFDEM_BIN, or build into %s)" % BUILD)
    os.makedirs(outdir, exist_ok=True)
    for f in os.listdir(outdir):
        os.remove(os.path.join(outdir, f))
    log = os.path.join(outdir, "log_view.txt")
    args = ["-physics", "energy", "-grid_cells", "%d,%d,%d" % c.cells, "-grid_lower", "%.17g,%.17g,%.17g" % c.lo,
            "-grid_upper", "%.17g,%.17g,%.17g" % c.hi, "-grid_ranks", "%d,1,1" % ranks,
            "-energy_metal_density", "%g" % RHO, "-energy_metal_specific_heat", "%g" % CP, "-energy_metal_conductivity", "%g" % K,
            "-energy_metal_latent_heat", "0", "-energy_metal_solidus", "1e5", "-energy_metal_liquidus", "2e5",
            "-energy_metal_boiling_point", "1e9", "-energy_interface_radiation", "0", "-energy_interface_convection", "0",
            "-energy_initial_temperature", "%g" % T0, "-energy_time_scheme", c.scheme,
            "-laser_power", "%g" % P, "-laser_radius", "%g" % R, "-laser_absorptivity", "%g" % ETA, "-laser_path", "0,0",
            "-dt", "%.17g" % c.dt, "-final_time", "%.17g" % c.t_end, "-max_steps", str(c.steps), "-monitor_every", str(c.w),
            "-energy_output_every", str(c.steps), "-output_dir", outdir, "-log_view", ":" + log] + extra
    cmd = mpi(ranks) + [exe] + args
    # rank 0's CPU time at the monitor lines of steps w and last, read from /proc as each line arrives: the
    # counterpart of OpenFOAM's ExecutionTime (rank 0's CPU time), which a busy machine inflates far less than wall time
    cpu_at, text = {}, []
    with Meter() as meter:
        p = subprocess.Popen(["stdbuf", "-oL"] + cmd, env=ENV, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, bufsize=1, cwd=ROOT)
        rank0 = None
        for line in p.stdout:
            text.append(line)
            m = re.match(r"step\s+(\d+)\s", line)
            if m and int(m.group(1)) in (c.w, c.last):
                rank0 = rank0 or rank_zero(p.pid)
                if rank0:
                    cpu_at[int(m.group(1))] = proc_cpu(rank0)
        rc = p.wait()
    out = "".join(text)
    with open(os.path.join(outdir, "stdout.txt"), "w") as f:
        f.write(" ".join(cmd) + "\n" + out)
    if rc != 0:
        lines = [l.strip() for l in out.splitlines() if l.strip().strip("-")]
        errors = [l for l in lines if "error" in l.lower()]
        raise RuntimeError("vofdem exit %d: %s (%s)" % (rc, (errors or lines or ["(no output)"])[0], os.path.join(outdir, "stdout.txt")))
    cpu = (cpu_at[c.last] - cpu_at[c.w]) / (c.timed * c.n) * 1e6 if c.w in cpu_at and c.last in cpu_at and cpu_at[c.w] is not None and cpu_at[c.last] is not None else float("nan")
    lines = [l for l in open(os.path.join(outdir, "monitor.csv")).read().splitlines() if l.strip()]
    cols = lines[0].split(",")
    rows = {int(float(r["step"])): r for r in (dict(zip(cols, l.split(","))) for l in lines[1:])}
    if c.w not in rows or c.last not in rows:
        raise RuntimeError("vofdem's monitor.csv lacks the rows of steps %d and %d" % (c.w, c.last))
    wall = float(rows[c.last]["wall_time_s"]) - float(rows[c.w]["wall_time_s"])
    # iterations of the monitor rows' steps inside the window (each row reports its own step)
    inside = [rows[s] for s in rows if c.w < s <= c.last]
    lin = statistics.median(float(r["energy_linear_iterations"]) for r in inside)
    its = statistics.median(float(r["energy_iterations"]) for r in inside)
    import h5py  # Debian's python3-h5py (install-deps)
    with h5py.File(os.path.join(outdir, "energy_%08d.h5" % c.steps), "r") as f:
        T = f["energy_temperature"][...]
    if T.shape != (c.cells[2], c.cells[1], c.cells[0]):
        raise RuntimeError("vofdem's temperature has shape %s" % (T.shape,))
    return wall / (c.timed * c.n) * 1e6, cpu, lin, its, T[-1], log, meter.foreign


def run_openfoam(c, ranks, solver, tol, case):
    absorbed = fh.make_case(case, ENV, c.lo, c.hi, c.cells, c.dt, c.steps, c.scheme, solver, tol, ranks, T0, K, A, ETA, P, R, (0.0, 0.0))
    with Meter() as meter:
        wall, cpu, iters = fh.run_timed(case, ranks, ENV, mpi)
    if len(cpu) != c.steps:
        raise RuntimeError("laplacianFoam ran %d steps, not %d (%s)" % (len(cpu), c.steps, case))
    # index k = after step k+1: the window of steps (w, last]
    t_cpu = cpu[c.last - 1] - cpu[c.w - 1]
    t_wall = wall[c.last - 1] - wall[c.w - 1]
    it = statistics.median(iters[c.w:c.last])
    return t_cpu / (c.timed * c.n) * 1e6, t_wall / (c.timed * c.n) * 1e6, it, absorbed, meter.foreign


# ---------------------------------------------------------------- vofdem's -log_view


def log_view_profile(path):
    """Seconds per event in the Energy stage of a -log_view file, with the stage's total and the run's total."""
    text = open(path).read()
    m = re.search(r"^\s*\d+:\s+Energy:\s+([0-9.eE+-]+)", text, re.M)
    total = re.search(r"^Time \(sec\):\s+([0-9.eE+-]+)", text, re.M)
    out = {"stage": float(m.group(1)) if m else float("nan"), "run": float(total.group(1)) if total else float("nan"), "events": {}}
    stage = re.search(r"--- Event Stage \d+: Energy\n(.*?)(?:--- Event Stage|\Z)", text, re.S)
    if stage:
        for line in stage.group(1).splitlines():
            f = line.split()
            if len(f) > 4 and re.match(r"^[A-Za-z]", f[0]) and re.match(r"^\d+$", f[1]):
                out["events"][f[0]] = (int(f[1]), float(f[3]))
    return out


# ---------------------------------------------------------------- the errors


def errors(c, top, ex, centre_ij):
    d = top - ex
    rr = np.hypot(*np.meshgrid(c.xc, c.yc))  # [y, x]
    disc = rr <= 2 * R
    rise = ex.max() - T0
    j, i = centre_ij
    return {"max": float(np.abs(d).max()), "rms": float(np.sqrt((d[disc] ** 2).mean())), "centre": float(d[j, i]),
            "rise": rise, "peak": float(top.max() - T0)}


def fmt_err(e, scale):
    return "%.3f K (%.2f %%)" % (e, 100 * e / scale)


def spread(v):
    return 100 * (max(v) - min(v)) / statistics.median(v) if len(v) > 1 else 0.0


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--cells-per-radius", type=int, default=8, help="R/h (default 8: h = 0.125 mm)")
    ap.add_argument("--half-width", type=int, default=5, help="the plate's half width in beam radii (default 5)")
    ap.add_argument("--depth", type=int, default=4, help="the plate's depth in beam radii (default 4)")
    ap.add_argument("--dt", type=float, default=1e-3, help="time step, both codes (s)")
    ap.add_argument("--end-time", type=float, default=0.1, help="end time, both codes (s; default R^2/(2a))")
    ap.add_argument("--scheme", choices=("bdf2", "euler"), default="bdf2", help="bdf2: vofdem bdf2, OpenFOAM backward; euler: both backward Euler")
    ap.add_argument("--warmup", type=int, default=5, help="steps before the timed window (and vofdem's monitor interval)")
    ap.add_argument("--repeats", type=int, default=3)
    ap.add_argument("--ranks", default="1,2")
    ap.add_argument("--foam-solvers", default="GAMG,PCG", help="OpenFOAM's T solvers to time (GAMG, PCG: PCG + DIC)")
    ap.add_argument("--foam-tolerance", type=float, default=1e-6, help="OpenFOAM's T tolerance (absolute, normalised residual; relTol 0)")
    ap.add_argument("--vofdem", default=None, help="the vofdem binary (default: $VOFDEM_BIN, then build/)")
    ap.add_argument("--vofdem-options", default="", help="extra vofdem options, e.g. --vofdem-options='-energy_pc_type none' (with '=')")
    ap.add_argument("--no-record", action="store_true", help="do not write the block into results/")
    a = ap.parse_args()
    ranks_list = [int(r) for r in a.ranks.split(",")]
    solvers = [s.strip() for s in a.foam_solvers.split(",") if s.strip()]
    c = Case(a)
    exe = vofdem_binary(a.vofdem)
    extra = a.vofdem_options.split()
    os.makedirs(WORK, exist_ok=True)
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout.strip()
    say("## %s, commit %s: `heat-vs-openfoam %s`" % (datetime.datetime.now().strftime("%Y-%m-%d %H:%M"), commit or "unknown", " ".join(sys.argv[1:])))
    say("vofdem binary: %s%s" % (exe, " (options: %s)" % a.vofdem_options if extra else ""))
    say("Gaussian spot P %g W, R %g m, eta %g on a plate %g x %g x %g mm (rho %g, cp %g, k %g: a %.3g m^2/s), no latent heat; "
        "%d x %d x %d = %d cells of h = R/%d; dt %g s, %d steps to t = %g s (%.2f R^2/a), %s (%s); timed steps %d..%d (%d) of each run"
        % (P, R, ETA, 1e3 * (c.hi[0] - c.lo[0]), 1e3 * (c.hi[1] - c.lo[1]), 1e3 * (c.hi[2] - c.lo[2]), RHO, CP, K, A, *c.cells, c.n, c.m,
           c.dt, c.steps, c.t_end, c.t_end * A / R ** 2, c.scheme, "vofdem bdf2 / OpenFOAM backward" if c.scheme == "bdf2" else "both backward Euler",
           c.w + 1, c.last, c.timed))
    say("OpenFOAM laplacianFoam: top fixedGradient (nonuniform List, exact face integrals of the beam / k), solvers %s to %g (relTol 0); "
        "vofdem: CG at its defaults (-energy_pc auto: Jacobi below 20 explicit limits, else PFMG; enthalpy tolerance 1e-6, each solve to a tenth of it)" % ("/".join(solvers), a.foam_tolerance))

    # the analytic solution on the top layer's centres, its quadrature checked, and the nearest images
    X, Y = np.meshgrid(c.xc, c.yc)  # [y, x]
    Z = np.full_like(X, -c.h / 2)
    ex = exact(X, Y, Z, c.t_end)
    ex2 = exact(X, Y, Z, c.t_end, quadrature(c.t_end, 512))
    scale = ex.max() - T0
    L, D = c.hi[0], -c.lo[2]
    images = sum(exact(X + sx, Y + sy, Z + sz, c.t_end) - T0 for sx, sy, sz in
                 ((2 * L, 0, 0), (-2 * L, 0, 0), (0, 2 * L, 0), (0, -2 * L, 0), (0, 0, 2 * D)))
    j0, i0 = int(np.argmin(np.abs(c.yc))), int(np.argmin(np.abs(c.xc)))
    disc = np.hypot(X, Y) <= 2 * R
    say("analytic (semi-infinite) peak rise on the top layer's centres %.3f K (quadrature checked to %.1e K); the five nearest image "
        "sources of the plate's adiabatic faces add at most %.2e K on the top layer (its edges), %.1e K within r <= 2 R"
        % (scale, float(np.abs(ex - ex2).max()), float(images.max()), float(images[disc].max())))
    load0 = os.getloadavg()
    say("load average at the start %.2f %.2f %.2f (%d cores)" % (*load0, os.cpu_count()))
    say()

    us = {}        # (code, ranks) -> [per repeat]; code "vofdem", "GAMG", "PCG"
    wall_us = {}   # OpenFOAM's wall-clock stamps
    cpu_us = {}    # ranks -> vofdem's rank-0 CPU time per cell-step
    foreign = {}   # (code, ranks) -> [cores]
    iters = {}
    err = {}
    tops = {}
    logs = {}
    failed = {}
    for rep in range(a.repeats):
        for ranks in ranks_list:
            line = "  repeat %d, %d rank%s:" % (rep + 1, ranks, "s" if ranks > 1 else "")
            if "vofdem" not in failed:
                try:
                    u, uc, lin, its, top, log, fl = run_vofdem(exe, c, ranks, os.path.join(WORK, "vofdem-%d" % ranks), extra)
                    us.setdefault(("vofdem", ranks), []).append(u)
                    cpu_us.setdefault(ranks, []).append(uc)
                    foreign.setdefault(("vofdem", ranks), []).append(fl)
                    iters[("vofdem", ranks)] = (its, lin)
                    logs.setdefault(ranks, []).append(log_view_profile(log))
                    if ("vofdem", ranks) not in err:
                        err[("vofdem", ranks)] = errors(c, top, ex, (j0, i0))
                        tops[("vofdem", ranks)] = top
                    line += " vofdem %.4f us (rank 0 CPU %.4f; %d lin. its/step, other load %.2f)" % (u, uc, lin, fl)
                except RuntimeError as e:
                    failed["vofdem"] = str(e)
                    line += " vofdem FAILED"
            for s in solvers:
                case = os.path.join(WORK, "foam-%s-%d" % (s, ranks))
                try:
                    u, uw, it, absorbed, fl = run_openfoam(c, ranks, s, a.foam_tolerance, case)
                except RuntimeError as e:
                    failed[s] = str(e).splitlines()[0]
                    line += ", OpenFOAM %s FAILED" % s
                    continue
                us.setdefault((s, ranks), []).append(u)
                wall_us.setdefault((s, ranks), []).append(uw)
                foreign.setdefault((s, ranks), []).append(fl)
                iters[(s, ranks)] = it
                if (s, ranks) not in err:
                    top = fh.final_field(case, ranks, ENV, c.steps, c.cells)[-1]
                    err[(s, ranks)] = errors(c, top, ex, (j0, i0))
                    tops[(s, ranks)] = top
                line += ", %s %.4f us (wall %.4f, %d its/step, other load %.2f)" % (s, u, uw, it, fl)
            say(line)
    load1 = os.getloadavg()
    say("load average at the end %.2f %.2f %.2f" % load1)
    for k, v in failed.items():
        say("%s FAILED: %s" % (k, v))
    say()

    med = {k: statistics.median(v) for k, v in us.items()}
    say("| ranks | code | cells | steps (timed) | us per cell-step, median | spread | other load (cores), max | max error | RMS error (r <= 2R) | error at the centre |")
    say("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |")
    verdict = []
    for ranks in ranks_list:
        avail = [s for s in solvers if (s, ranks) in med]
        best = min(avail, key=lambda s: med[(s, ranks)]) if avail else None
        for code in ["vofdem"] + solvers:
            if (code, ranks) not in med:
                say("| %d | %s | %d | %d (%d) | failed | | | | | |" % (ranks, code, c.n, c.steps, c.timed))
                continue
            e = err[(code, ranks)]
            name = ("vofdem (%s)" % (a.vofdem_options or "CG, its defaults")) if code == "vofdem" else "OpenFOAM laplacianFoam, %s%s%s" % (
                code, " + DIC" if code == "PCG" else "", " (faster)" if code == best else "")
            say("| %d | %s | %d | %d (%d) | %.4f | %.0f %% | %.2f | %s | %s | %+.3f K |" % (
                ranks, name, c.n, c.steps, c.timed, med[(code, ranks)], spread(us[(code, ranks)]), max(foreign[(code, ranks)]),
                fmt_err(e["max"], scale), fmt_err(e["rms"], scale), e["centre"]))
        if best and ("vofdem", ranks) in med:
            ratios = [f / v for f, v in zip(us[(best, ranks)], us[("vofdem", ranks)])]
            rm = statistics.median(ratios)
            ev, ef = err[("vofdem", ranks)], err[(best, ranks)]
            # equal: within 5 % (both codes solve the same discrete problem; they differ by OpenFOAM's solver tolerance)
            verdict.append((ranks, rm, ev["max"] <= ef["max"] * 1.05 and ev["rms"] <= ef["rms"] * 1.05))
            say("| %d | **OpenFOAM %s / vofdem** | | | **%.2f** (paired median of %d; %.2f-%.2f) | | | | | |" % (
                ranks, best, rm, len(ratios), min(ratios), max(ratios)))
            wr = [f / v for f, v in zip(wall_us[(best, ranks)], us[("vofdem", ranks)])]
            say("| %d | OpenFOAM %s / vofdem, wall clock in both | | | %.2f (paired median; %.2f-%.2f) | | | | | |" % (
                ranks, best, statistics.median(wr), min(wr), max(wr)))
            cr = [f / v for f, v in zip(us[(best, ranks)], cpu_us[ranks]) if v == v]
            if cr:
                say("| %d | OpenFOAM %s / vofdem, rank 0's CPU time in both | | | %.2f (paired median; %.2f-%.2f) | | | | | |" % (
                    ranks, best, statistics.median(cr), min(cr), max(cr)))
    say()
    say("error: code minus the semi-infinite solution on the %d x %d top-layer cell centres at t = %g s (analytic peak rise %.3f K; %% of it)"
        % (c.cells[0], c.cells[1], c.t_end, scale))
    if err:
        least = min(e["max"] for e in err.values())
        say("finite plate: the nearest images (%.3f K at most) are %.0f %% of the smallest max error (%.3f K): the semi-infinite solution %s"
            % (float(images.max()), 100 * float(images.max()) / least, least,
               "holds on the whole top layer" if images.max() < 0.1 * least else "does NOT hold at the plate's edges: enlarge the plate or shorten the run"))
    say("iterations per step: vofdem %s; OpenFOAM %s" % (
        ", ".join("%d rank(s) %g enthalpy / %g CG" % (r, *iters[("vofdem", r)]) for r in ranks_list if ("vofdem", r) in iters),
        ", ".join("%s %d rank(s) %g" % (s, r, iters[(s, r)]) for s in solvers for r in ranks_list if (s, r) in iters)))
    for ranks in ranks_list:
        if cpu_us.get(ranks):
            say("vofdem, %d rank(s): rank 0's CPU time %.4f us per cell-step (median) against its wall clock %.4f" % (
                ranks, statistics.median(cpu_us[ranks]), med[("vofdem", ranks)]))
        for s in solvers:
            if (s, ranks) in wall_us and (s, ranks) in med:
                say("OpenFOAM %s, %d rank(s): wall-clock stamps %.4f us per cell-step (median) against ExecutionTime %.4f" % (
                    s, ranks, statistics.median(wall_us[(s, ranks)]), med[(s, ranks)]))
    for ranks in ranks_list[1:]:
        for code in ["vofdem"] + solvers:
            if (code, ranks) in tops and (code, ranks_list[0]) in tops:
                say("%s: top layer on %d ranks against %d: max difference %.2e K" % (
                    code, ranks, ranks_list[0], float(np.abs(tops[(code, ranks)] - tops[(code, ranks_list[0])]).max())))
    if ("vofdem", ranks_list[0]) in tops:
        for s in solvers:
            if (s, ranks_list[0]) in tops:
                say("vofdem against OpenFOAM %s (%d rank(s)): top layer max difference %.2e K" % (
                    s, ranks_list[0], float(np.abs(tops[("vofdem", ranks_list[0])] - tops[(s, ranks_list[0])]).max())))
    # where vofdem's time goes (median run by stage time)
    for ranks in ranks_list:
        if ranks not in logs:
            continue
        lv = sorted(logs[ranks], key=lambda d: d["stage"])[len(logs[ranks]) // 2]
        ev = lv["events"]
        st = lv["stage"]
        parts = []
        for name in ("KSPSolve", "PCApply", "MatMult", "PCSetUp", "MatZeroEntries", "MatAssemblyEnd", "VecCopy"):
            if name in ev:
                parts.append("%s %.1f %%" % (name, 100 * ev[name][1] / st))
        known = sum(ev[n][1] for n in ("KSPSolve", "PCSetUp", "MatZeroEntries", "MatAssemblyBegin", "MatAssemblyEnd", "VecCopy", "VecSet",
                                       "VecAXPBYCZ", "VecSum") if n in ev)  # PCSetUp runs before KSPSolve's event; scatters are inside MatMult
        say("vofdem -log_view, %d rank(s): Energy stage %.3f s of %.3f s (%.2f us per cell-step over all %d steps): %s; outside PETSc's "
            "events (vofdem's own loops: Properties, Residual, Assemble's MatSetValuesStencil, the laser) %.1f %%"
            % (ranks, st, lv["run"], st / (c.steps * c.n) * 1e6, c.steps, ", ".join(parts), 100 * (st - known) / st))
    worst = max((max(v) for v in foreign.values()), default=0.0)
    if max(load0[0], load1[0]) > 1.5 or worst > 0.25:
        say("WARNING: the machine was not quiet (load average %.2f / %.2f, up to %.2f cores used by others during a run): "
            "the absolute figures are unreliable; the paired ratios less so" % (load0[0], load1[0], worst))
    else:
        say("the machine was quiet (load average %.2f / %.2f, at most %.2f cores used by others during a run)" % (load0[0], load1[0], worst))
    if verdict:
        say("target (vofdem >= 3x OpenFOAM per cell-step at equal or smaller error, on every rank count): %s (%s)" % (
            "met" if all(r >= 3 and ok for _, r, ok in verdict) else "NOT met",
            "; ".join("%d rank(s) %.2fx, error %s" % (rk, r, "equal (within 5 %) or smaller" if ok else "LARGER") for rk, r, ok in verdict)))
    if not a.no_record:
        record.prepend_block(RESULTS, "# heat-vs-openfoam (scripts/bench/heat-vs-openfoam), newest first", OUT, ROOT)


if __name__ == "__main__":
    main()
