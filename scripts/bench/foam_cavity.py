"""OpenFOAM v1912 side of flow-vs-openfoam: writes an icoFoam case of the 3-D lid-driven cavity, runs it,
and reads its log and its cell-centred velocity field.

The case: unit cube, blockMesh N^3, lid (1 0 0) on the y = 1 face, nu = 0.01 (Re 100), central
differences in space and Euler in time as in the tutorial cavity, PISO with 2 correctors, dt = 0.5/N
(CFL 0.5 at the lid speed). Pressure: GAMG with a Gauss-Seidel smoother (the tutorial's PCG + DIC needs
~200 iterations per step at 64^3, GAMG ~10; see docs/petsc-notes.md, "OpenFOAM's pressure solver"), same tolerances as
the tutorial (1e-6 absolute, 0.05 relative in the first corrector, 0 in the final one). Smoother:
GaussSeidel was the fastest on 1 rank at 64^3 (1.7-1.8 us per cell-step against 2.0 for DIC and
symGaussSeidel and 2.3-2.5 for DICGaussSeidel; results/bench-flow-vs-openfoam.md).
"""
import os
import re
import shutil
import subprocess
import time

import numpy as np

NU = 0.01
HEADER = """FoamFile
{
    version     2.0;
    format      ascii;
    class       %s;
    object      %s;
}
"""


def write(path, cls, obj, body):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(HEADER % (cls, obj) + body)


def control_dict(n, steps=None, end_time=None, write_every=None, purge=2):
    """Timing runs (steps) write nothing; steady runs (end_time) write U and p every write_every."""
    dt = 0.5 / n
    if steps is not None:
        end = "%.17g" % (steps * dt)
        writing = "writeControl    timeStep;\nwriteInterval   %d;\n" % (10 * steps + 10)
    else:
        end = "%.17g" % end_time
        writing = "writeControl    adjustableRunTime;\nwriteInterval   %g;\npurgeWrite      %d;\n" % (write_every, purge)
    return """application     icoFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         %s;
deltaT          %.17g;
%swriteFormat     ascii;
writePrecision  10;
writeCompression off;
timeFormat      general;
timePrecision   10;
runTimeModifiable false;
""" % (end, dt, writing)


FV_SCHEMES = """ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; grad(p) Gauss linear; }
divSchemes { default none; div(phi,U) Gauss linear; }
laplacianSchemes { default Gauss linear orthogonal; }
interpolationSchemes { default linear; }
snGradSchemes { default orthogonal; }
"""


def fv_solution(smoother="GaussSeidel"):
    return """solvers
{
    p
    {
        solver          GAMG;
        smoother        %s;
        tolerance       1e-06;
        relTol          0.05;
        nPreSweeps      0;
        nPostSweeps     2;
        cacheAgglomeration true;
        agglomerator    faceAreaPair;
        nCellsInCoarsestLevel 10;
        mergeLevels     1;
    }
    pFinal
    {
        $p;
        relTol          0;
    }
    U
    {
        solver          smoothSolver;
        smoother        symGaussSeidel;
        tolerance       1e-05;
        relTol          0;
    }
}
PISO
{
    nCorrectors     2;
    nNonOrthogonalCorrectors 0;
    pRefCell        0;
    pRefValue       0;
}
""" % smoother


def block_mesh_dict(n):
    return """convertToMeters 1;
vertices ( (0 0 0) (1 0 0) (1 1 0) (0 1 0) (0 0 1) (1 0 1) (1 1 1) (0 1 1) );
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1) );
edges ();
boundary
(
    movingWall { type wall; faces ( (3 7 6 2) ); }
    fixedWalls { type wall; faces ( (0 4 7 3) (2 6 5 1) (1 5 4 0) (0 3 2 1) (4 5 6 7) ); }
);
mergePatchPairs ();
""" % (n, n, n)


U0 = """dimensions      [0 1 -1 0 0 0 0];
internalField   uniform (0 0 0);
boundaryField
{
    movingWall { type fixedValue; value uniform (1 0 0); }
    fixedWalls { type noSlip; }
}
"""
P0 = """dimensions      [0 2 -2 0 0 0 0];
internalField   uniform 0;
boundaryField
{
    movingWall { type zeroGradient; }
    fixedWalls { type zeroGradient; }
}
"""


def run(cmd, cwd, env, log):
    with open(log, "w") as f:
        p = subprocess.run(cmd, cwd=cwd, env=env, stdout=f, stderr=subprocess.STDOUT)
    if p.returncode != 0:
        raise RuntimeError("command failed (%s): %s\n%s" % (log, " ".join(cmd), open(log).read()[-3000:]))


def signature(n, ranks, smoother="GaussSeidel", **control):
    """Everything that defines a run (to reuse a finished steady run)."""
    return "ranks %d\n%s%s%s%s" % (ranks, control_dict(n, **control), FV_SCHEMES, fv_solution(smoother), block_mesh_dict(n))


def make_case(case, n, ranks, env, smoother="GaussSeidel", **control):
    """A fresh case directory; the mesh is made once per n and copied."""
    if os.path.isdir(case):
        shutil.rmtree(case)
    write(os.path.join(case, "system/controlDict"), "dictionary", "controlDict", control_dict(n, **control))
    write(os.path.join(case, "system/fvSchemes"), "dictionary", "fvSchemes", FV_SCHEMES)
    write(os.path.join(case, "system/fvSolution"), "dictionary", "fvSolution", fv_solution(smoother))
    write(os.path.join(case, "system/blockMeshDict"), "dictionary", "blockMeshDict", block_mesh_dict(n))
    write(os.path.join(case, "system/decomposeParDict"), "dictionary", "decomposeParDict",
          # split along x into equal halves: the smallest interface a 2-way split of a cube can have
          "numberOfSubdomains %d;\nmethod simple;\ncoeffs { n (%d 1 1); }\n" % (ranks, ranks))
    write(os.path.join(case, "constant/transportProperties"), "dictionary", "transportProperties",
          "nu              %g;\n" % NU)
    write(os.path.join(case, "0/U"), "volVectorField", "U", U0)
    write(os.path.join(case, "0/p"), "volScalarField", "p", P0)
    mesh_cache = os.path.join(os.path.dirname(case), "mesh-%d" % n)
    if not os.path.isdir(os.path.join(mesh_cache, "constant/polyMesh")):
        if os.path.isdir(mesh_cache):
            shutil.rmtree(mesh_cache)
        shutil.copytree(case, mesh_cache)
        run(["blockMesh"], mesh_cache, env, os.path.join(mesh_cache, "log.blockMesh"))
    shutil.copytree(os.path.join(mesh_cache, "constant/polyMesh"), os.path.join(case, "constant/polyMesh"))
    if ranks > 1:
        run(["decomposePar", "-force"], case, env, os.path.join(case, "log.decomposePar"))


def solver_cmd(ranks, mpi):
    return (mpi(ranks) + ["icoFoam", "-parallel"]) if ranks > 1 else (mpi(1) + ["icoFoam"])


def run_timed(case, ranks, env, mpi):
    """Runs icoFoam, stamping each `ExecutionTime` line with the wall clock as it arrives.
    Returns (wall stamps, ExecutionTime values, p iterations per step, the last largest Courant
    number); index k = after step k+1."""
    log = os.path.join(case, "log.icoFoam")
    wall, cpu, iters, step_iters, courant = [], [], [], 0, float("nan")
    with open(log, "w") as f:
        p = subprocess.Popen(["stdbuf", "-oL"] + solver_cmd(ranks, mpi), cwd=case, env=env, stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True, bufsize=1)
        for line in p.stdout:
            t = time.monotonic()
            f.write(line)
            m = re.match(r"Courant Number mean: \S+ max: (\S+)", line)
            if m:
                courant = float(m.group(1))
            m = re.search(r"Solving for p, .* No Iterations (\d+)", line)
            if m:
                step_iters += int(m.group(1))
            m = re.match(r"ExecutionTime = ([0-9.eE+-]+) s", line)
            if m:
                wall.append(t)
                cpu.append(float(m.group(1)))
                iters.append(step_iters)
                step_iters = 0
        rc = p.wait()
    if rc != 0:
        raise RuntimeError("icoFoam failed (%s):\n%s" % (log, open(log).read()[-3000:]))
    return wall, cpu, iters, courant


def time_dirs(d):
    out = []
    for name in os.listdir(d):
        try:
            out.append((float(name), name))
        except ValueError:
            pass
    return sorted(out)


def read_vectors(path, n):
    """The internalField of an ascii volVectorField with n cells, as an (n, 3) array."""
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<vector>\s*(\d+)\s*\(", text)
    if not m or int(m.group(1)) != n:
        raise RuntimeError("%s: no internalField of %d vectors" % (path, n))
    body = text[m.end():text.index("boundaryField", m.end())]
    vals = np.array(body.replace("(", " ").replace(")", " ").split()[: 3 * n], dtype=float)
    return vals.reshape(n, 3)


def cell_field(case, n, time_name):
    """U on the N^3 cell centres as an array [i, j, k, comp]; blockMesh numbers cells x fastest, then y, z."""
    u = read_vectors(os.path.join(case, time_name, "U"), n ** 3)
    return u.reshape(n, n, n, 3).transpose(2, 1, 0, 3)
