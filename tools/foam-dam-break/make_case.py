"""Write an OpenFOAM (interFoam, VOF) case of the dam break against a wall at Buchner's scale (issue #35).

A mesh-based, two-phase (water and air) solver on the geometry of cases/dam-break.toml: a column H = 0.6 m high
and 2H wide at the left of a tank 5.366 H long (3.2196 m), open at the top at 3 H. It tells whether a
free-surface flow solved without particles reads P1's slow first rise as bowwave does, or the fast rise of
Buchner's experiment and of the thesis's δ-SPH: a cross-check, outside the product and its tests.

Walls are free slip (`--walls slip`, the thesis's and bowwave's default) or no slip (`--walls noSlip`, laminar,
water's ν unless `--nu` is given). No surface tension unless `--sigma` (bowwave has none). The mesh is uniform,
H/dx cells per H (two blocks in x and in y so that the column's edges lie on cell faces). Wall pressure is
sampled on the right wall's faces every step (`patchProbes`, p = p_rgh + ρ g·h, zero in the air at rest) at
every face from the floor to 0.45 m, so that any sensor's face average can be formed afterwards (reduce.py).

Usage: python3 make_case.py OUTDIR --res 80 [--walls slip|noSlip] [--turbulence laminar|kOmegaSST] [--nu 1e-6]
       [--sigma 0] [--end 1.2]
Then:  cd OUTDIR && blockMesh && setFields && interFoam      (OpenFOAM v1912, Debian's `openfoam` package)
"""
import argparse
import os

H = 0.6
COLUMN = 2.0 * H
TANK = 3.2196
TOP = 3.0 * H
G = 9.81

HEADER = """FoamFile
{{
    version     2.0;
    format      ascii;
    class       {cls};
    location    "{loc}";
    object      {obj};
}}
"""


def write(root, rel, cls, body):
    path = os.path.join(root, rel)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    loc, obj = os.path.split(rel)
    with open(path, "w") as f:
        f.write(HEADER.format(cls=cls, loc=loc, obj=obj))
        f.write(body)


WALLS = ("leftWall", "rightWall", "lowerWall")


def field(dims, internal, wall, atmosphere):
    """A field file's body: `wall` (the entries inside each wall's braces) on the three walls, `atmosphere` on
    the open top, empty front and back."""
    body = f"dimensions {dims};\n\ninternalField uniform {internal};\n\nboundaryField\n{{\n"
    for name, entry in [(w, wall) for w in WALLS] + [("atmosphere", atmosphere)]:
        body += f"    {name}\n    {{\n        {entry}\n    }}\n"
    return body + "    frontAndBack\n    {\n        type empty;\n    }\n}\n"


def block_mesh(res):
    dx = H / res
    nx1 = int(round(COLUMN / dx))
    nx2 = int(round((TANK - COLUMN) / dx))
    ny1 = res
    ny2 = int(round((TOP - H) / dx))
    xs = [0.0, COLUMN, TANK]
    ys = [0.0, H, TOP]
    verts = []
    for z in (0.0, dx):
        for y in ys:
            for x in xs:
                verts.append((x, y, z))

    def v(i, j, k):  # i along x (0..2), j along y (0..2), k front/back
        return k * 9 + j * 3 + i

    blocks = []
    for j, ny in ((0, ny1), (1, ny2)):
        for i, nx in ((0, nx1), (1, nx2)):
            ids = [v(i, j, 0), v(i + 1, j, 0), v(i + 1, j + 1, 0), v(i, j + 1, 0),
                   v(i, j, 1), v(i + 1, j, 1), v(i + 1, j + 1, 1), v(i, j + 1, 1)]
            blocks.append(f"    hex ({' '.join(map(str, ids))}) ({nx} {ny} 1) simpleGrading (1 1 1)")

    def quad(a, b, c, d):
        return f"            ({a} {b} {c} {d})"

    left = [quad(v(0, j, 0), v(0, j, 1), v(0, j + 1, 1), v(0, j + 1, 0)) for j in (0, 1)]
    right = [quad(v(2, j, 0), v(2, j + 1, 0), v(2, j + 1, 1), v(2, j, 1)) for j in (0, 1)]
    lower = [quad(v(i, 0, 0), v(i + 1, 0, 0), v(i + 1, 0, 1), v(i, 0, 1)) for i in (0, 1)]
    top = [quad(v(i, 2, 0), v(i, 2, 1), v(i + 1, 2, 1), v(i + 1, 2, 0)) for i in (0, 1)]
    body = "convertToMeters 1;\n\nvertices\n(\n"
    body += "\n".join(f"    ({x:.6f} {y:.6f} {z:.8f})" for x, y, z in verts)
    body += "\n);\n\nblocks\n(\n" + "\n".join(blocks) + "\n);\n\nedges\n(\n);\n\nboundary\n(\n"
    for name, kind, faces in (("leftWall", "wall", left), ("rightWall", "wall", right),
                              ("lowerWall", "wall", lower), ("atmosphere", "patch", top)):
        body += f"    {name}\n    {{\n        type {kind};\n        faces\n        (\n" + "\n".join(faces)
        body += "\n        );\n    }\n"
    body += "    frontAndBack\n    {\n        type empty;\n        faces\n        (\n"
    faces = []
    for j in (0, 1):
        for i in (0, 1):
            faces.append(quad(v(i, j, 0), v(i, j + 1, 0), v(i + 1, j + 1, 0), v(i + 1, j, 0)))
            faces.append(quad(v(i, j, 1), v(i + 1, j, 1), v(i + 1, j + 1, 1), v(i, j + 1, 1)))
    body += "\n".join(faces) + "\n        );\n    }\n);\n"
    return body, dx, ny1 + ny2


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("out")
    ap.add_argument("--res", type=int, default=80, help="H/dx (cells per H), default 80")
    ap.add_argument("--walls", choices=["slip", "noSlip"], default="slip")
    ap.add_argument("--nu", type=float, default=1e-6, help="water's kinematic viscosity, m²/s (default 1e-6)")
    ap.add_argument("--sigma", type=float, default=0.0, help="surface tension, N/m (default 0: bowwave has none)")
    ap.add_argument("--end", type=float, default=1.2, help="end time, s (default 1.2: t√(g/H) 4.85)")
    ap.add_argument("--max-co", type=float, default=0.25, help="largest Courant number (default 0.25)")
    ap.add_argument("--turbulence", choices=["laminar", "kOmegaSST"], default="laminar",
                    help="laminar (default) or k-omega SST with wall functions (with --walls noSlip: the "
                    "experiments' turbulent boundary layer, modelled)")
    a = ap.parse_args()
    root = a.out
    mesh, dx, _ = block_mesh(a.res)
    write(root, "system/blockMeshDict", "dictionary", mesh)

    wall_u = "slip" if a.walls == "slip" else "noSlip"
    write(root, "0/U", "volVectorField",
          field("[0 1 -1 0 0 0 0]", "(0 0 0)", f"type {wall_u};",
                "type pressureInletOutletVelocity;\n        value uniform (0 0 0);"))
    write(root, "0/p_rgh", "volScalarField",
          field("[1 -1 -2 0 0 0 0]", "0", "type fixedFluxPressure;\n        value uniform 0;",
                "type totalPressure;\n        p0 uniform 0;"))
    write(root, "0/alpha.water", "volScalarField",
          field("[0 0 0 0 0 0 0]", "0", "type zeroGradient;",
                "type inletOutlet;\n        inletValue uniform 0;\n        value uniform 0;"))

    write(root, "constant/g", "uniformDimensionedVectorField",
          f"dimensions [0 1 -2 0 0 0 0];\nvalue (0 {-G} 0);\n")
    write(root, "constant/transportProperties", "dictionary",
          f"phases (water air);\n\nwater\n{{\n    transportModel Newtonian;\n    nu {a.nu};\n    rho 1000;\n}}\n\n"
          f"air\n{{\n    transportModel Newtonian;\n    nu 1.48e-05;\n    rho 1;\n}}\n\nsigma {a.sigma};\n")
    if a.turbulence == "laminar":
        write(root, "constant/turbulenceProperties", "dictionary", "simulationType laminar;\n")
    else:
        write(root, "constant/turbulenceProperties", "dictionary",
              "simulationType RAS;\n\nRAS\n{\n    RASModel kOmegaSST;\n    turbulence on;\n    printCoeffs on;\n}\n")
        # Still water: k 1e-6 m²/s², ω 1 1/s (ν_t = k/ω = 1e-6 m²/s, water's ν), wall functions on the walls.
        for name, dims, value, wall in (("k", "[0 2 -2 0 0 0 0]", 1e-6, "kqRWallFunction"),
                                        ("omega", "[0 0 -1 0 0 0 0]", 1.0, "omegaWallFunction"),
                                        ("nut", "[0 2 -1 0 0 0 0]", 0.0, "nutkWallFunction")):
            top = ("type calculated;\n        value uniform 0;" if name == "nut" else
                   f"type inletOutlet;\n        inletValue uniform {value};\n        value uniform {value};")
            write(root, f"0/{name}", "volScalarField",
                  field(dims, value, f"type {wall};\n        value uniform {value};", top))

    # Wall pressure on the right wall: a patch probe at every face centre from the floor to 0.45 m.
    n_probe = int(0.45 / dx)
    pts = "\n".join(f"            ({TANK:.6f} {(j + 0.5) * dx:.8f} {0.5 * dx:.8f})" for j in range(n_probe))
    control = f"""application interFoam;
startFrom latestTime;
startTime 0;
stopAt endTime;
endTime {a.end};
deltaT 1e-5;
writeControl adjustable;
writeInterval 0.025;
purgeWrite 0;
writeFormat binary;
writePrecision 8;
writeCompression off;
timeFormat general;
timePrecision 8;
runTimeModifiable no;
adjustTimeStep yes;
maxCo {a.max_co};
maxAlphaCo {a.max_co};
maxDeltaT 1e-3;

functions
{{
    wallPressure
    {{
        type patchProbes;
        libs ("libsampling.so");
        patches (rightWall);
        fields (p);
        writeControl timeStep;
        writeInterval 1;
        probeLocations
        (
{pts}
        );
    }}
}}
"""
    write(root, "system/controlDict", "dictionary", control)
    write(root, "system/setFieldsDict", "dictionary",
          "defaultFieldValues\n(\n    volScalarFieldValue alpha.water 0\n);\n\nregions\n(\n"
          f"    boxToCell\n    {{\n        box (-1 -1 -1) ({COLUMN} {H} 1);\n"
          "        fieldValues\n        (\n            volScalarFieldValue alpha.water 1\n        );\n    }\n);\n")
    write(root, "system/fvSchemes", "dictionary", """ddtSchemes
{
    default Euler;
}
gradSchemes
{
    default Gauss linear;
}
divSchemes
{
    div(rhoPhi,U) Gauss linearUpwind grad(U);
    div(phi,alpha) Gauss vanLeer;
    div(phirb,alpha) Gauss linear;
    div(phi,k) Gauss upwind;
    div(phi,omega) Gauss upwind;
    div(((rho*nuEff)*dev2(T(grad(U))))) Gauss linear;
}
laplacianSchemes
{
    default Gauss linear corrected;
}
interpolationSchemes
{
    default linear;
}
snGradSchemes
{
    default corrected;
}
wallDist
{
    method meshWave;
}
""")
    write(root, "system/fvSolution", "dictionary", """solvers
{
    "alpha.water.*"
    {
        nAlphaCorr 2;
        nAlphaSubCycles 1;
        cAlpha 1;
        MULESCorr yes;
        nLimiterIter 5;
        solver smoothSolver;
        smoother symGaussSeidel;
        tolerance 1e-8;
        relTol 0;
    }
    "pcorr.*"
    {
        solver PCG;
        preconditioner DIC;
        tolerance 1e-5;
        relTol 0;
    }
    p_rgh
    {
        solver PCG;
        preconditioner DIC;
        tolerance 1e-7;
        relTol 0.05;
    }
    p_rghFinal
    {
        $p_rgh;
        relTol 0;
    }
    "(U|k|omega).*"
    {
        solver smoothSolver;
        smoother symGaussSeidel;
        tolerance 1e-6;
        relTol 0;
        minIter 1;
    }
}
PIMPLE
{
    momentumPredictor no;
    nOuterCorrectors 1;
    nCorrectors 3;
    nNonOrthogonalCorrectors 0;
}
relaxationFactors
{
    equations
    {
        ".*" 1;
    }
}
""")
    print(f"{root}: H/dx {a.res}, dx {dx:.5f} m, walls {a.walls}, {a.turbulence}, {n_probe} wall probes")


if __name__ == "__main__":
    main()
