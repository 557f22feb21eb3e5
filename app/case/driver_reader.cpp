// Reads drivers[i] (docs/case-format.md, "drivers[i]").
#include "app/case/driver_reader.hpp"

#include "app/case/motion_reader.hpp"

namespace heavesim {

void read_driver(const NodeReader& item, const std::string& name, CaseDefinition& definition,
                 const ExpressionContext& expressions) {
  item.expect_section("drivers[i]");
  DriverDefinition def;
  def.name = name;
  def.joint = item["joint"].text();
  def.coordinate = static_cast<int>(item.optional("coordinate") ? item["coordinate"].integer() : 0);
  const std::shared_ptr<const TimeFunction> function = read_motion(item, name, expressions);
  def.motion = [function](double t) { return (*function)(t); };
  definition.drivers.push_back(std::move(def));
}

}  // namespace heavesim
