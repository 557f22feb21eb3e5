#include "bench/mjcf_writer.hpp"

#include <fmt/format.h>

#include <functional>
#include <vector>

namespace heavesim::bench {

std::string to_mjcf(const samples::BenchModel& bench) {
  std::vector<std::vector<int>> children(bench.links.size());
  std::vector<int> roots;
  for (std::size_t i = 0; i < bench.links.size(); ++i)
    (bench.links[i].parent < 0 ? roots : children[bench.links[i].parent]).push_back(static_cast<int>(i));
  std::function<std::string(int)> body = [&](int i) {
    const samples::BenchLink& link = bench.links[i];
    std::string text = fmt::format("<body name=\"link{}\" pos=\"{} {} {}\">", i, link.offset.x(), link.offset.y(),
                                   link.offset.z());
    text += link.free ? "<freejoint/>"
                      : fmt::format("<joint type=\"hinge\" axis=\"{} {} {}\"/>", link.axis.x(), link.axis.y(),
                                    link.axis.z());
    text += fmt::format("<inertial pos=\"{} {} {}\" mass=\"{}\" diaginertia=\"{} {} {}\"/>", link.com.x(),
                        link.com.y(), link.com.z(), link.mass, link.inertia.x(), link.inertia.y(), link.inertia.z());
    for (int child : children[i]) text += body(child);
    return text + "</body>";
  };
  std::string xml = "<mujoco model=\"" + bench.name + "\"><option gravity=\"0 0 -9.81\"/><worldbody>";
  for (int root : roots) xml += body(root);
  return xml + "</worldbody></mujoco>";
}

}  // namespace heavesim::bench
