"""Run by scripts/check-paraview under pvpython: reads each XDMF index with ParaView's XDMF reader
and checks every time level against the index itself (counts and array names)."""
import sys
import xml.etree.ElementTree as ET

from paraview import simple  # noqa: E402  (pvpython only)


def expected(path):
    """(time, points, cells, attribute names) per time level, from the index."""
    levels = []
    for grid in ET.parse(path).getroot().iter("Grid"):
        if grid.get("GridType") != "Uniform":
            continue
        topo = grid.find("Topology")
        if topo.get("TopologyType") == "3DCoRectMesh":  # a uniform grid: nodes z y x
            nodes = [int(d) for d in topo.get("Dimensions").split()]
            points = nodes[0] * nodes[1] * nodes[2]
            elements = (nodes[0] - 1) * (nodes[1] - 1) * (nodes[2] - 1)
        else:
            elements = int(topo.get("NumberOfElements"))
            points = int(grid.find("Geometry/DataItem").get("Dimensions").split()[0])
        names = [a.get("Name") for a in grid.findall("Attribute")]
        levels.append((float(grid.find("Time").get("Value")), points, elements, names))
    return levels


def check(path):
    levels = expected(path)
    reader = simple.XDMFReader(FileNames=[path])
    times = list(reader.TimestepValues) if len(levels) > 1 else [levels[0][0]]
    bad = 0
    if len(times) != len(levels):
        print("not ok %s: ParaView sees %d time levels, the index has %d" % (path, len(times), len(levels)))
        return 1
    for t, (tx, npts, ncells, names) in zip(times, levels):
        reader.UpdatePipeline(t)
        info = reader.GetDataInformation()
        arrays = set(reader.PointData.keys()) | set(reader.CellData.keys())
        missing = [n for n in names if n not in arrays]
        ok = info.GetNumberOfPoints() == npts and info.GetNumberOfCells() == ncells and not missing
        bad += not ok
        print("%s %s t=%.6e: %d points, %d cells, arrays %s%s" % ("ok" if ok else "not ok", path, t, info.GetNumberOfPoints(),
              info.GetNumberOfCells(), ",".join(sorted(arrays)), (" missing " + ",".join(missing)) if missing else ""))
    return bad


def main():
    if len(sys.argv) < 2:
        print(__doc__)
        return 2
    return 1 if sum(check(p) for p in sys.argv[1:]) else 0


sys.exit(main())
