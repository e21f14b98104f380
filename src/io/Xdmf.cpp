#include "vofdem/io/Xdmf.hpp"

#include <cstdio>

namespace vofdem {

namespace {

std::string DataItem(const std::string &dims, const std::string &file, const std::string &dataset, const char *type = "Float", int precision = 8) {
  char buf[512];
  std::snprintf(buf, sizeof buf, "<DataItem Dimensions=\"%s\" NumberType=\"%s\" Precision=\"%d\" Format=\"HDF\">%s:%s</DataItem>", dims.c_str(), type, precision,
                file.c_str(), dataset.c_str());
  return buf;
}

}  // namespace

std::string XdmfIndexText(const std::string &name, const std::vector<XdmfEntry> &entries) {
  std::string t = "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf Version=\"2.0\">\n <Domain>\n";
  t += "  <Grid Name=\"" + name + "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  char buf[256];
  for (const XdmfEntry &e : entries) {
    const std::string n = std::to_string(e.nodes);
    std::snprintf(buf, sizeof buf, "   <Grid Name=\"%s %d\" GridType=\"Uniform\">\n    <Time Value=\"%.17g\"/>\n", name.c_str(), (int)e.step, (double)e.time);
    t += buf;
    if (e.cells[0] >= 0) {  // XDMF orders structured dimensions z, y, x
      const std::string cellDims = std::to_string(e.cells[2]) + " " + std::to_string(e.cells[1]) + " " + std::to_string(e.cells[0]);
      std::snprintf(buf, sizeof buf, "    <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"%d %d %d\"/>\n", (int)e.cells[2] + 1, (int)e.cells[1] + 1, (int)e.cells[0] + 1);
      t += buf;
      std::snprintf(buf, sizeof buf,
                    "    <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n     <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">%.17g %.17g %.17g</DataItem>\n",
                    (double)e.origin[2], (double)e.origin[1], (double)e.origin[0]);
      t += buf;
      std::snprintf(buf, sizeof buf, "     <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">%.17g %.17g %.17g</DataItem>\n    </Geometry>\n",
                    (double)e.spacing[2], (double)e.spacing[1], (double)e.spacing[0]);
      t += buf;
      for (const XdmfAttribute &a : e.attributes)
        t += "    <Attribute Name=\"" + a.name + "\" AttributeType=\"" + (a.components == 3 ? "Vector" : "Scalar") + "\" Center=\"Cell\">\n     " +
             DataItem(a.components == 1 ? cellDims : cellDims + " " + std::to_string(a.components), e.file, a.dataset) + "\n    </Attribute>\n";
      t += "   </Grid>\n";
      continue;
    }
    if (e.segments >= 0) {
      const std::string s = std::to_string(e.segments);
      t += "    <Topology TopologyType=\"Polyline\" NumberOfElements=\"" + s + "\" NodesPerElement=\"2\">\n     " +
           DataItem(s + " 2", e.file, e.connectivity, "Int", 8) + "\n    </Topology>\n";
    } else {
      t += "    <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + n + "\" NodesPerElement=\"1\"/>\n";
    }
    t += "    <Geometry GeometryType=\"XYZ\">\n     " + DataItem(n + " 3", e.file, e.geometry) + "\n    </Geometry>\n";
    for (const XdmfAttribute &a : e.attributes) {
      const std::string count = a.cell ? std::to_string(e.segments) : n;
      t += "    <Attribute Name=\"" + a.name + "\" AttributeType=\"" + (a.components == 3 ? "Vector" : "Scalar") + "\" Center=\"" + (a.cell ? "Cell" : "Node") +
           "\">\n     " + DataItem(a.components == 1 ? count : count + " " + std::to_string(a.components), e.file, a.dataset) + "\n    </Attribute>\n";
    }
    t += "   </Grid>\n";
  }
  t += "  </Grid>\n </Domain>\n</Xdmf>\n";
  return t;
}

}  // namespace vofdem
