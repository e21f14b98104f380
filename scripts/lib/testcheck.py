"""What the Python tests share (test/output, test/checkpoint): a list of failed checks that prints as it goes, and a vofdem run
under mpiexec whose failure is a failed check (with its output shown)."""
import csv
import os
import subprocess
import sys

ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1", OMP_NUM_THREADS="1")
failures = []


def check(ok, what):
    print("%s %s" % ("ok" if ok else "not ok", what))
    if not ok:
        failures.append(what)


def run_vofdem(exe, n, args, timeout=300):
    """Runs `mpiexec -n N --oversubscribe exe args`; a non-zero exit is a failed check."""
    p = subprocess.run(["mpiexec", "--oversubscribe", "-n", str(n), exe] + args, env=ENV, capture_output=True, text=True, timeout=timeout)
    check(p.returncode == 0, "vofdem on %d rank(s) exits 0" % n)
    if p.returncode:
        print(p.stdout, p.stderr)
    return p


def finish():
    """Ends a test script: exit 1 with the count of failed checks, else print that all passed."""
    if failures:
        print("FAIL: %d check(s) failed" % len(failures))
        sys.exit(1)
    print("all checks passed")


def read_particles(path):
    """A particle CSV (-dem_save_particles) as a list of {column: float}; [] if the run that writes it failed."""
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def monitor_rows(out):
    """A run's monitor table (OUT/monitor.csv) as a list of {column: float}."""
    with open(os.path.join(out, "monitor.csv")) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]
