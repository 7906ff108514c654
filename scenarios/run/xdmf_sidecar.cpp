#include "scenarios/run/xdmf_sidecar.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "scenarios/run/output_support.hpp"

namespace carom {

using output_detail::base_name;
using output_detail::xdmf_path_of;

namespace {

constexpr const char* kHeader =
    "<?xml version=\"1.0\" ?>\n"
    "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n"
    "<Xdmf Version=\"3.0\">\n"
    "  <Domain>\n";
constexpr const char* kFooter = "  </Domain>\n</Xdmf>\n";

/// One HDF5 dataset reference: `dimensions` values of the given type at data_file:/path.
void data_item(std::ostringstream& xml, const std::string& indent, const std::string& dimensions,
               const char* type, int precision, const std::string& reference) {
  xml << indent << "<DataItem Dimensions=\"" << dimensions << "\" NumberType=\"" << type
      << "\" Precision=\"" << precision << "\" Format=\"HDF\">" << reference << "</DataItem>\n";
}

/// A point or cell attribute (scalar, or a 3-vector when `vector`) read from `reference`.
void attribute(std::ostringstream& xml, const std::string& name, const char* center,
               const std::string& dimensions, bool vector, const char* type, int precision,
               const std::string& reference) {
  xml << "        <Attribute Name=\"" << name << "\" AttributeType=\""
      << (vector ? "Vector" : "Scalar") << "\" Center=\"" << center << "\">\n";
  data_item(xml, "          ", dimensions + (vector ? " 3" : ""), type, precision, reference);
  xml << "        </Attribute>\n";
}

/// One snapshot's grid of run.xmf.
void particle_grid(std::ostringstream& xml, const std::string& data_file, const XdmfSnapshot& s) {
  const std::string where = data_file + ":/snapshots/" + s.name + "/";
  const std::string n = std::to_string(s.count);
  xml << "      <Grid Name=\"particles_" << s.name << "\" GridType=\"Uniform\">\n"
      << "        <Time Value=\"" << s.time << "\"/>\n"
      << "        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" << n
      << "\" NodesPerElement=\"1\">\n";
  data_item(xml, "          ", n, "Int", 8, data_file + ":/" + vertex_dataset_of(s.count));
  xml << "        </Topology>\n"
      << "        <Geometry GeometryType=\"XYZ\">\n";
  data_item(xml, "          ", n + " 3", "Float", 8, where + "position");
  xml << "        </Geometry>\n";
  attribute(xml, "radius", "Node", n, false, "Float", 8, where + "radius");
  attribute(xml, "velocity", "Node", n, true, "Float", 8, where + "velocity");
  attribute(xml, "spin", "Node", n, true, "Float", 8, where + "spin");
  attribute(xml, "species", "Node", n, false, "Int", 4, where + "species");
  attribute(xml, "id", "Node", n, false, "Int", 8, where + "id");
  xml << "      </Grid>\n";
}

/// What follows the last grid of either sidecar: the temporal collection's end and kFooter.
const std::string kTail = std::string("    </Grid>\n") + kFooter;

std::string particles_xml(const std::string& data_file,
                          const std::vector<XdmfSnapshot>& snapshots) {
  std::ostringstream xml;
  xml.precision(17);
  xml << kHeader
      << "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const XdmfSnapshot& s : snapshots) particle_grid(xml, data_file, s);
  xml << kTail;
  return xml.str();
}

/// One snapshot's grid of run_gas.xmf: cell-centred fields on a uniform grid, nodes = cells + 1
/// per axis, listed z y x. The origin and spacing say Precision="8": without it ParaView reads
/// inline values as 4-byte floats.
void gas_grid(std::ostringstream& xml, const std::string& data_file, const XdmfSnapshot& s, const XdmfGasGrid& gas) {
  const std::array<int, 3>& c = gas.cells;
  const std::string dims =
      std::to_string(c[2]) + " " + std::to_string(c[1]) + " " + std::to_string(c[0]);
  const std::string nodes =
      std::to_string(c[2] + 1) + " " + std::to_string(c[1] + 1) + " " + std::to_string(c[0] + 1);
  const std::string where = data_file + ":/snapshots/" + s.name + "/gas/";
  xml << "      <Grid Name=\"gas_" << s.name << "\" GridType=\"Uniform\">\n"
      << "        <Time Value=\"" << s.time << "\"/>\n"
      << "        <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"" << nodes << "\"/>\n"
      << "        <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
      << "          <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
         "Format=\"XML\">"
      << gas.lower.z() << " " << gas.lower.y() << " " << gas.lower.x() << "</DataItem>\n"
      << "          <DataItem Dimensions=\"3\" NumberType=\"Float\" Precision=\"8\" "
         "Format=\"XML\">"
      << gas.spacing.z() << " " << gas.spacing.y() << " " << gas.spacing.x() << "</DataItem>\n"
      << "        </Geometry>\n";
  attribute(xml, "porosity", "Cell", dims, false, "Float", 8, where + "porosity");
  attribute(xml, "pressure", "Cell", dims, false, "Float", 8, where + "pressure");
  attribute(xml, "velocity", "Cell", dims, true, "Float", 8, where + "velocity");
  xml << "      </Grid>\n";
}

std::string gas_xml(const std::string& data_file, const std::vector<XdmfSnapshot>& snapshots,
                    const XdmfGasGrid& gas) {
  std::ostringstream xml;
  xml.precision(17);
  xml << kHeader << "    <Grid Name=\"gas\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const XdmfSnapshot& s : snapshots) gas_grid(xml, data_file, s, gas);
  xml << kTail;
  return xml.str();
}

/// Writes `grid` over the closing tail of the sidecar at `path` and the tail after it, in one
/// write: the file grows by the grid alone, and is whole before and after. False (nothing
/// written) when the file does not end in the tail.
bool append_before_tail(const std::string& path, const std::string& grid) {
  const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat info {};
  bool ok = ::fstat(fd, &info) == 0 && S_ISREG(info.st_mode) &&
            static_cast<std::size_t>(info.st_size) >= kTail.size();
  if (ok) {
    const off_t at = info.st_size - static_cast<off_t>(kTail.size());
    std::string end(kTail.size(), '\0');
    ok = ::pread(fd, end.data(), end.size(), at) == static_cast<ssize_t>(end.size()) && end == kTail;
    if (ok) {
      const std::string text = grid + kTail;
      const ssize_t written = ::pwrite(fd, text.data(), text.size(), at);
      if (written != static_cast<ssize_t>(text.size())) {
        const int error = errno;
        // Put the tail back where it was, so the file stays whole.
        const ssize_t restored = ::pwrite(fd, kTail.data(), kTail.size(), at);
        if (restored == static_cast<ssize_t>(kTail.size())) (void)::ftruncate(fd, info.st_size);
        ::close(fd);
        throw std::runtime_error(path + ": cannot write the XDMF sidecar: " +
                                 std::strerror(written < 0 ? error : ENOSPC));
      }
    }
  }
  ::close(fd);
  return ok;
}

/// Writes `text` to `path` through a temporary file renamed over it.
void replace_text_file(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  {
    std::ofstream out(temporary, std::ios::trunc);
    out << text;
    if (!out.flush()) {
      out.close();
      std::remove(temporary.c_str());
      throw std::runtime_error(temporary + ": cannot write the XDMF sidecar");
    }
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0)
    throw std::runtime_error(path + ": cannot replace the XDMF sidecar: " + std::strerror(errno));
}

}  // namespace

std::string gas_xdmf_path_of(const std::string& h5_path) {
  const std::string particles = xdmf_path_of(h5_path);
  return particles.substr(0, particles.size() - 4) + "_gas.xmf";
}

std::string vertex_dataset_of(std::size_t count) {
  return "xdmf/vertices_" + std::to_string(count);
}

void write_vertex_cells(const h5::File& file, std::size_t count) {
  if (!file.contains("xdmf")) file.create_group("xdmf");
  const std::string name = vertex_dataset_of(count);
  if (file.contains(name)) return;
  std::vector<std::int64_t> vertices(count);
  std::iota(vertices.begin(), vertices.end(), std::int64_t{0});
  file.write(name, vertices);
}

void write_xdmf_sidecars(const std::string& h5_path, const std::vector<XdmfSnapshot>& snapshots,
                         const XdmfGasGrid* gas) {
  const std::string data_file = base_name(h5_path);
  replace_text_file(xdmf_path_of(h5_path), particles_xml(data_file, snapshots));
  if (gas != nullptr)
    replace_text_file(gas_xdmf_path_of(h5_path), gas_xml(data_file, snapshots, *gas));
}

bool append_xdmf_snapshot(const std::string& h5_path, const XdmfSnapshot& snapshot, const XdmfGasGrid* gas) {
  const std::string data_file = base_name(h5_path);
  std::ostringstream particles, fields;
  particles.precision(17);
  fields.precision(17);
  particle_grid(particles, data_file, snapshot);
  if (gas != nullptr) {
    gas_grid(fields, data_file, snapshot, *gas);
    // The gas file first: when it cannot take the grid, neither file has it (a full rewrite
    // follows).
    if (!append_before_tail(gas_xdmf_path_of(h5_path), fields.str())) return false;
  }
  return append_before_tail(xdmf_path_of(h5_path), particles.str());
}

}  // namespace carom
