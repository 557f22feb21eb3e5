#include "validation/oracles/spring_crane.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Geometry>

namespace heavesim::oracle {
namespace {

struct SpringState {
  Eigen::Vector3d direction;  // unit, from the boom point to the mast head
  double tension;             // N
  Eigen::Vector3d point;      // m, the boom point
};

SpringState spring_state(const SpringCrane& c, double elevation) {
  const Eigen::Vector3d e(std::cos(elevation), 0.0, std::sin(elevation));
  const Eigen::Vector3d point = c.spring_point * e, head(0.0, 0.0, c.mast_height);
  const Eigen::Vector3d span = head - point;
  const double length = span.norm();
  return {span / length, c.stiffness * (length - c.rest_length), point};
}

}  // namespace

double spring_crane_moment(const SpringCrane& c, double elevation) {
  const SpringState s = spring_state(c, elevation);
  const double spring = s.tension * s.point.cross(s.direction).dot(Eigen::Vector3d(0.0, -1.0, 0.0));
  const double weights = (c.boom_mass * c.boom_length / 2 + c.payload_mass * c.boom_length) * c.g * std::cos(elevation);
  return spring - weights;
}

SpringCraneEquilibrium spring_crane_equilibrium(const SpringCrane& c, double lower, double upper) {
  double m_lower = spring_crane_moment(c, lower);
  if (m_lower * spring_crane_moment(c, upper) > 0.0) throw std::runtime_error("spring crane: no sign change in bracket");
  // Bisection to the last bit: 200 halvings exceed the 52 a double can resolve.
  for (int k = 0; k < 200 && upper - lower > 0.0; ++k) {
    const double middle = 0.5 * (lower + upper);
    if (middle <= lower || middle >= upper) break;
    const double m_middle = spring_crane_moment(c, middle);
    if ((m_middle < 0.0) == (m_lower < 0.0)) {
      lower = middle;
      m_lower = m_middle;
    } else {
      upper = middle;
    }
  }
  SpringCraneEquilibrium result;
  result.elevation = 0.5 * (lower + upper);
  const SpringState s = spring_state(c, result.elevation);
  result.spring_tension = s.tension;
  result.foot_reaction = (c.boom_mass + c.payload_mass) * c.g * Eigen::Vector3d::UnitZ() - s.tension * s.direction;
  return result;
}

}  // namespace heavesim::oracle
