// A ParaView collection (.pvd): the list of (time, file) pairs of one output series. It is
// rewritten whole after every file, so that ParaView can open a running (or stopped) analysis
// and see every step written so far.
#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "geompm/io/vtk_writer.hpp"
#include "geompm/io/vtk_writer_xml.hpp"

namespace geompm {

PvdSeries::PvdSeries(std::filesystem::path pvd_file) : pvd_file_(std::move(pvd_file)) {}

void PvdSeries::add(double time, const std::string& relative_file) {
  if (!std::isfinite(time))
    throw std::invalid_argument(
        fmt::format("{}: time {} of '{}' is not finite", pvd_file_.string(), time, relative_file));
  entries_.emplace_back(time, relative_file);
  write();
}

void PvdSeries::restore(std::vector<std::pair<double, std::string>> entries) {
  entries_ = std::move(entries);
  // An empty series has no file, as in a run that never stopped.
  if (entries_.empty())
    std::filesystem::remove(pvd_file_);
  else
    write();
}

void PvdSeries::write() const {
  std::string xml =
      "<?xml version=\"1.0\"?>\n"
      "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      "  <Collection>\n";
  for (const auto& [t, file] : entries_) {
    // "{}" is the shortest text that reads back as the same double: full precision, so that
    // steps closer than any fixed number of digits stay distinct in ParaView's time list.
    xml += fmt::format("    <DataSet timestep=\"{}\" group=\"\" part=\"0\" file=\"{}\"/>\n", t,
                       vtk_xml::escape(file));
  }
  xml += "  </Collection>\n</VTKFile>\n";
  write_file_atomically(pvd_file_, xml);
}

}  // namespace geompm
