"""OpenFOAM v1912 side of vof-vs-openfoam: writes an interIsoFoam case of the Martin & Moyce (1952) dam
break, runs it, and reads its front position and its cost.

The case is the one of config/scenes/dam-break.yaml (V5): a water column a = 0.05715 m wide and 2a high
at the left wall of a closed tank 5a x 2.5a, quasi-2-D (one cell deep, `empty` front and back), walls
everywhere (noSlip, fixedFluxPressure), water 1000 kg/m^3 and 1e-6 m^2/s, air 1 kg/m^3 and 1.8e-5 m^2/s
(the scene's viscosities), gravity -9.81 along y. Numerics as in Debian's interIsoFoam/damBreak tutorial
(isoAdvector, PIMPLE with 3 correctors, GAMG on p_rgh, maxAlphaCo 0.5, maxCo 10): the peer at its own
recommended settings. Surface tension as given (the vofdem scene has none: 0).

The front position is the wetted length of the bottom row of cells, sum(alpha_i h) from the left wall:
the same definition is applied to vofdem's field.
"""
import math
import os
import re
import shutil
import subprocess

import numpy as np

from foam_cavity import write  # the FoamFile header and file writer

A = 0.05715  # m, Martin & Moyce's column width (2.25 in)
G = 9.81
def scaled_time(t):
    """Martin & Moyce's T = t sqrt(2 g / a)."""
    return t * math.sqrt(2 * G / A)


def control_dict(end_time, write_times):
    return """application     interIsoFoam;
startFrom       startTime;
startTime       0;
stopAt          endTime;
endTime         %.17g;
deltaT          1e-5;
writeControl    adjustable;
writeInterval   %.17g;
purgeWrite      0;
writeFormat     ascii;
writePrecision  10;
writeCompression off;
timeFormat      general;
timePrecision   10;
runTimeModifiable no;
adjustTimeStep  yes;
maxCo           10;
maxAlphaCo      0.5;
maxDeltaT       1;
""" % (end_time, write_times)


FV_SCHEMES = """ddtSchemes { default Euler; }
gradSchemes { default Gauss linear; }
divSchemes
{
    div(rhoPhi,U)  Gauss limitedLinearV 1;
    div(phi,alpha)  Gauss vanLeer;
    div(phirb,alpha) Gauss interfaceCompression;
    div(((rho*nuEff)*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes { default Gauss linear corrected; }
interpolationSchemes { default linear; }
snGradSchemes { default corrected; }
fluxRequired { default no; p_rgh; pcorr; alpha.water; }
"""

FV_SOLUTION = """solvers
{
    "alpha.water.*"
    {
        isoFaceTol      1e-6;
        surfCellTol     1e-6;
        nAlphaBounds    3;
        snapTol         1e-12;
        clip            true;
        nAlphaSubCycles 1;
        cAlpha          1;
    }
    "pcorr.*" { solver PCG; preconditioner DIC; tolerance 1e-10; relTol 0; }
    p_rgh { solver GAMG; smoother DICGaussSeidel; tolerance 1e-7; relTol 0.05; }
    p_rghFinal { $p_rgh; tolerance 1e-7; relTol 0; }
    U { solver PBiCGStab; preconditioner DILU; tolerance 1e-6; relTol 0; }
}
PIMPLE
{
    momentumPredictor no;
    nCorrectors     3;
    nOuterCorrectors 1;
    nNonOrthogonalCorrectors 0;
    pRefCell        0;
    pRefValue       0;
}
"""


def block_mesh_dict(nx, ny):
    lx, ly, lz = 5 * A, 2.5 * A, 5 * A / nx
    return """convertToMeters 1;
vertices ( (0 0 0) (%.17g 0 0) (%.17g %.17g 0) (0 %.17g 0) (0 0 %.17g) (%.17g 0 %.17g) (%.17g %.17g %.17g) (0 %.17g %.17g) );
blocks ( hex (0 1 2 3 4 5 6 7) (%d %d 1) simpleGrading (1 1 1) );
edges ();
boundary
(
    walls { type wall; faces ( (0 4 7 3) (2 6 5 1) (1 5 4 0) (3 7 6 2) ); }
    frontAndBack { type empty; faces ( (0 3 2 1) (4 5 6 7) ); }
);
mergePatchPairs ();
""" % (lx, lx, ly, ly, lz, lx, lz, lx, ly, lz, ly, lz, nx, ny)


FIELDS = {
    "U": ("volVectorField", """dimensions [0 1 -1 0 0 0 0];
internalField uniform (0 0 0);
boundaryField { walls { type noSlip; } frontAndBack { type empty; } }
"""),
    "p_rgh": ("volScalarField", """dimensions [1 -1 -2 0 0 0 0];
internalField uniform 0;
boundaryField { walls { type fixedFluxPressure; value uniform 0; } frontAndBack { type empty; } }
"""),
    "alpha.water": ("volScalarField", """dimensions [0 0 0 0 0 0 0];
internalField uniform 0;
boundaryField { walls { type zeroGradient; } frontAndBack { type empty; } }
"""),
}


def make_case(case, nx, ny, ranks, env, run, end_time, write_every, sigma=0.0, nu_air=1.8e-5, nu_water=1e-6):
    if os.path.isdir(case):
        shutil.rmtree(case)
    write(os.path.join(case, "system/controlDict"), "dictionary", "controlDict", control_dict(end_time, write_every))
    write(os.path.join(case, "system/fvSchemes"), "dictionary", "fvSchemes", FV_SCHEMES)
    write(os.path.join(case, "system/fvSolution"), "dictionary", "fvSolution", FV_SOLUTION)
    write(os.path.join(case, "system/blockMeshDict"), "dictionary", "blockMeshDict", block_mesh_dict(nx, ny))
    write(os.path.join(case, "system/decomposeParDict"), "dictionary", "decomposeParDict",
          "numberOfSubdomains %d;\nmethod simple;\ncoeffs { n (%d 1 1); }\n" % (ranks, ranks))
    write(os.path.join(case, "system/setFieldsDict"), "dictionary", "setFieldsDict",
          "defaultFieldValues ( volScalarFieldValue alpha.water 0 );\n"
          "regions ( boxToCell { box (-1 -1 -1) (%.17g %.17g 1); fieldValues ( volScalarFieldValue alpha.water 1 ); } );\n" % (A, 2 * A))
    write(os.path.join(case, "constant/transportProperties"), "dictionary", "transportProperties",
          "phases (water air);\nwater { transportModel Newtonian; nu %g; rho 1000; }\nair { transportModel Newtonian; nu %g; rho 1; }\nsigma %g;\n"
          % (nu_water, nu_air, sigma))
    write(os.path.join(case, "constant/turbulenceProperties"), "dictionary", "turbulenceProperties", "simulationType laminar;\n")
    write(os.path.join(case, "constant/g"), "uniformDimensionedVectorField", "g", "dimensions [0 1 -2 0 0 0 0];\nvalue (0 %g 0);\n" % -G)
    for name, (cls, body) in FIELDS.items():
        write(os.path.join(case, "0", name), cls, name, body)
    run(["blockMesh"], case, env, os.path.join(case, "log.blockMesh"))
    run(["setFields"], case, env, os.path.join(case, "log.setFields"))
    if ranks > 1:
        run(["decomposePar", "-force"], case, env, os.path.join(case, "log.decomposePar"))


def parse_log(log):
    """Steps taken and the solver's own wall clock (ClockTime of the last step, s)."""
    steps, clock, first = 0, 0.0, None
    for line in open(log):
        if line.startswith("Time = "):
            steps += 1
        m = re.match(r"ExecutionTime = \S+ s\s+ClockTime = (\S+) s", line)
        if m:
            clock = float(m.group(1))
            first = clock if first is None else first
    return steps, clock


def read_scalars(path, n):
    text = open(path).read()
    m = re.search(r"internalField\s+nonuniform\s+List<scalar>\s*(\d+)\s*\(", text)
    if not m:
        m2 = re.search(r"internalField\s+uniform\s+(\S+);", text)
        if m2:
            return np.full(n, float(m2.group(1)))
        raise RuntimeError("%s: no internalField" % path)
    if int(m.group(1)) != n:
        raise RuntimeError("%s: %s values, expected %d" % (path, m.group(1), n))
    body = text[m.end():text.index(")", m.end())]
    return np.array(body.split()[:n], dtype=float)


def front_positions(case, nx, ny, ranks, env, run):
    """(t, x_front) at every written time; fields are reconstructed first on several ranks."""
    if ranks > 1:
        run(["reconstructPar", "-fields", "(alpha.water)"], case, env, os.path.join(case, "log.reconstructPar"))
    h = 5 * A / nx
    out = []
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if t <= 0 or not os.path.exists(os.path.join(case, name, "alpha.water")):
            continue
        alpha = read_scalars(os.path.join(case, name, "alpha.water"), nx * ny).reshape(ny, nx)  # x fastest
        out.append((t, float(alpha[0].sum() * h)))
    return sorted(out)
