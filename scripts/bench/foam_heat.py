"""OpenFOAM v1912 side of heat-vs-openfoam: writes a laplacianFoam case of a Gaussian spot heating a plate,
runs it, and reads its log and its cell-centred temperature.

The case: the box [x0, x1] x [y0, y1] x [z0, z1] in blockMesh cells nx x ny x nz (uniform), T0 everywhere,
dT/dt = div(DT grad T) with DT = k / (rho cp). The top face (z = z1) is a fixedGradient patch whose gradient
is a nonuniform List, face by face: q_f / k, q_f = eta P_f / A_f with P_f the exact integral of the Gaussian
I = 2P/(pi R^2) exp(-2 r^2/R^2) over the face (a product of erf differences: what vofdem deposits into the
top cell of the column under that face), so each top cell receives eta P_f through its top face. The other
faces are zeroGradient (adiabatic). Laplacian Gauss linear orthogonal (the mesh is orthogonal; no corrector),
ddt Euler or backward (BDF2, which takes Euler on its first step, as vofdem's BDF2 does).
The T solver: GAMG (Gauss-Seidel smoother, the flow bench's fastest) or PCG + DIC, to an absolute tolerance
(OpenFOAM's normalised residual), relTol 0.
"""
import math
import os
import re
import shutil
import subprocess
import time

import numpy as np

from foam_cavity import write  # the FoamFile header and file writer


def control_dict(dt, steps):
    """Writes only the last step (writeInterval = steps): the field for the errors."""
    return """application     laplacianFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         %.17g;
deltaT          %.17g;
writeControl    timeStep;
writeInterval   %d;
writeFormat     ascii;
writePrecision  12;
writeCompression off;
timeFormat      general;
timePrecision   12;
runTimeModifiable false;
""" % (steps * dt, dt, steps)


def fv_schemes(scheme):
    return """ddtSchemes { default %s; }
gradSchemes { default Gauss linear; }
divSchemes { default none; }
laplacianSchemes { default Gauss linear orthogonal; }
interpolationSchemes { default linear; }
snGradSchemes { default orthogonal; }
""" % {"bdf2": "backward", "euler": "Euler"}[scheme]


def fv_solution(solver, tolerance):
    if solver == "GAMG":
        body = """        solver          GAMG;
        smoother        GaussSeidel;
        nPreSweeps      0;
        nPostSweeps     2;
        cacheAgglomeration true;
        agglomerator    faceAreaPair;
        nCellsInCoarsestLevel 10;
        mergeLevels     1;
"""
    elif solver == "PCG":
        body = """        solver          PCG;
        preconditioner  DIC;
"""
    else:
        raise ValueError(solver)
    return """solvers
{
    T
    {
%s        tolerance       %g;
        relTol          0;
    }
}
SIMPLE
{
    nNonOrthogonalCorrectors 0;
}
""" % (body, tolerance)


def block_mesh_dict(lo, hi, cells):
    (x0, y0, z0), (x1, y1, z1) = lo, hi
    v = [(x0, y0, z0), (x1, y0, z0), (x1, y1, z0), (x0, y1, z0), (x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]
    return """convertToMeters 1;
vertices ( %s );
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d %d) simpleGrading (1 1 1) );
edges ();
boundary
(
    top { type patch; faces ( (4 5 6 7) ); }
    sides { type wall; faces ( (0 4 7 3) (2 6 5 1) (1 5 4 0) (3 7 6 2) (0 3 2 1) ); }
);
mergePatchPairs ();
""" % (" ".join("(%.17g %.17g %.17g)" % p for p in v), cells[0], cells[1], cells[2])


def run(cmd, cwd, env, log):
    with open(log, "w") as f:
        p = subprocess.run(cmd, cwd=cwd, env=env, stdout=f, stderr=subprocess.STDOUT)
    if p.returncode != 0:
        raise RuntimeError("command failed (%s): %s\n%s" % (log, " ".join(cmd), open(log).read()[-3000:]))


def _foam_list(text, kind):
    """The entries of the first `N ( ... )` list of an ascii polyMesh file."""
    m = re.search(r"\n(\d+)\s*\n\(", text)
    if not m:
        raise RuntimeError("no list in the %s file" % kind)
    return int(m.group(1)), text[m.end():]


def top_faces(case):
    """(x0, x1, y0, y1) of each face of the top patch, in the patch's order, from the ascii polyMesh."""
    mesh = os.path.join(case, "constant", "polyMesh")
    n, body = _foam_list(open(os.path.join(mesh, "points")).read(), "points")
    pts = np.array([p.split() for p in re.findall(r"\(([^()]*)\)", body)[:n]], dtype=float)
    btext = open(os.path.join(mesh, "boundary")).read()
    m = re.search(r"\btop\s*\{[^}]*?nFaces\s+(\d+);[^}]*?startFace\s+(\d+);", btext, re.S)
    if not m:
        raise RuntimeError("no top patch in %s" % os.path.join(mesh, "boundary"))
    nfaces, start = int(m.group(1)), int(m.group(2))
    nf, fbody = _foam_list(open(os.path.join(mesh, "faces")).read(), "faces")
    faces = re.findall(r"\d+\(([^()]*)\)", fbody)[:nf]
    out = np.empty((nfaces, 4))
    for i in range(nfaces):
        p = pts[[int(j) for j in faces[start + i].split()]]
        out[i] = (p[:, 0].min(), p[:, 0].max(), p[:, 1].min(), p[:, 1].max())
    return out


def face_powers(bounds, power, radius, centre):
    """The exact beam power through each rectangle: P/4 [erf(sqrt2 (x1-X)/R) - erf(sqrt2 (x0-X)/R)] [... y ...]."""
    erf = np.vectorize(math.erf)
    s = math.sqrt(2.0) / radius
    fx = erf(s * (bounds[:, 1] - centre[0])) - erf(s * (bounds[:, 0] - centre[0]))
    fy = erf(s * (bounds[:, 3] - centre[1])) - erf(s * (bounds[:, 2] - centre[1]))
    return 0.25 * power * fx * fy


def make_case(case, env, lo, hi, cells, dt, steps, scheme, solver, tolerance, ranks, T0, k, diffusivity, eta, power, radius, centre):
    """A fresh case; the mesh and the boundary field are made once per grid and copied."""
    if os.path.isdir(case):
        shutil.rmtree(case)
    key = "mesh-%dx%dx%d-%s" % (cells[0], cells[1], cells[2], "-".join("%.6g" % v for v in (*lo, *hi, eta * power, radius, *centre, k, T0)))
    cache = os.path.join(os.path.dirname(case), key)
    if not os.path.isfile(os.path.join(cache, "0", "T")):
        if os.path.isdir(cache):
            shutil.rmtree(cache)
        write(os.path.join(cache, "system/controlDict"), "dictionary", "controlDict", control_dict(dt, steps))
        write(os.path.join(cache, "system/blockMeshDict"), "dictionary", "blockMeshDict", block_mesh_dict(lo, hi, cells))
        run(["blockMesh"], cache, env, os.path.join(cache, "log.blockMesh"))
        b = top_faces(cache)
        area = (b[:, 1] - b[:, 0]) * (b[:, 3] - b[:, 2])
        grad = eta * face_powers(b, power, radius, centre) / area / k
        write(os.path.join(cache, "0", "T"), "volScalarField", "T", """dimensions      [0 0 0 1 0 0 0];
internalField   uniform %.17g;
boundaryField
{
    top
    {
        type            fixedGradient;
        gradient        nonuniform List<scalar>
%d
(
%s
)
;
    }
    sides { type zeroGradient; }
}
""" % (T0, grad.size, "\n".join("%.17g" % g for g in grad)))
        with open(os.path.join(cache, "absorbed_W"), "w") as f:
            f.write("%.17g\n" % float((grad * area).sum() * k))
    write(os.path.join(case, "system/controlDict"), "dictionary", "controlDict", control_dict(dt, steps))
    write(os.path.join(case, "system/fvSchemes"), "dictionary", "fvSchemes", fv_schemes(scheme))
    write(os.path.join(case, "system/fvSolution"), "dictionary", "fvSolution", fv_solution(solver, tolerance))
    write(os.path.join(case, "system/decomposeParDict"), "dictionary", "decomposeParDict",
          # halves along x, as vofdem's -grid_ranks 2,1,1
          "numberOfSubdomains %d;\nmethod simple;\ncoeffs { n (%d 1 1); }\n" % (ranks, ranks))
    write(os.path.join(case, "constant/transportProperties"), "dictionary", "transportProperties",
          "DT              [0 2 -1 0 0 0 0] %.17g;\n" % diffusivity)
    shutil.copytree(os.path.join(cache, "constant", "polyMesh"), os.path.join(case, "constant", "polyMesh"))
    shutil.copytree(os.path.join(cache, "0"), os.path.join(case, "0"))
    if ranks > 1:
        run(["decomposePar", "-force"], case, env, os.path.join(case, "log.decomposePar"))
    return float(open(os.path.join(cache, "absorbed_W")).read())


def run_timed(case, ranks, env, mpi):
    """Runs laplacianFoam, stamping each `ExecutionTime` line with the wall clock as it arrives.
    Returns (wall stamps, ExecutionTime values, T solver iterations per step); index k = after step k+1."""
    log = os.path.join(case, "log.laplacianFoam")
    cmd = mpi(ranks) + ["laplacianFoam"] + (["-parallel"] if ranks > 1 else [])
    wall, cpu, iters, step_iters = [], [], [], 0
    with open(log, "w") as f:
        p = subprocess.Popen(["stdbuf", "-oL"] + cmd, cwd=case, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, bufsize=1)
        for line in p.stdout:
            t = time.monotonic()
            f.write(line)
            m = re.search(r"Solving for T, .* No Iterations (\d+)", line)
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
        raise RuntimeError("laplacianFoam failed (%s):\n%s" % (log, open(log).read()[-3000:]))
    return wall, cpu, iters


def final_field(case, ranks, env, steps, cells):
    """T on the cells as an array [z, y, x] (blockMesh numbers cells x fastest, then y, z)."""
    if ranks > 1:
        run(["reconstructPar", "-latestTime"], case, env, os.path.join(case, "log.reconstructPar"))
    times = []
    for name in os.listdir(case):
        try:
            times.append((float(name), name))
        except ValueError:
            pass
    t, name = max(times)
    if t <= 0:
        raise RuntimeError("%s: no time directory after 0" % case)
    text = open(os.path.join(case, name, "T")).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", text)
    n = cells[0] * cells[1] * cells[2]
    if not m or int(m.group(1)) != n:
        raise RuntimeError("%s: no internalField of %d values" % (os.path.join(case, name, "T"), n))
    vals = np.array(text[m.end():text.index(")", m.end())].split(), dtype=float)
    return vals.reshape(cells[2], cells[1], cells[0])
