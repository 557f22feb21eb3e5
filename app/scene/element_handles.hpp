#pragma once
// Typed handles on the force elements whose state the run summary reads (compensator
// strokes, gas states, contact forces), recorded by the scene where it builds each one,
// so that the summary is bound to their types at compile time instead of searching the
// system's elements.
#include <cstddef>
#include <memory>
#include <vector>

#include "control/active/active_compensator.hpp"
#include "control/pneumatic/pneumatic_compensator.hpp"
#include "kernel/elements/ground_contact.hpp"
#include "kernel/system/multibody_system.hpp"

namespace heavesim {

template <class Element>
struct ElementHandle {
  const Element* element = nullptr;  // owned by the scene's MultibodySystem
  /// Index in MultibodySystem::force_elements(): the element's state is
  /// y.segment(system.state_offset(index), element->state_size()).
  std::size_t index = 0;
};

/// In the order the scene adds them to the system.
struct SummarisedElements {
  std::vector<ElementHandle<PneumaticCompensator>> pneumatic_compensators;
  std::vector<ElementHandle<ActiveCompensator>> active_compensators;
  std::vector<ElementHandle<GroundContact>> ground_contacts;
};

/// Adds `element` to `system` and returns its handle.
template <class Element>
ElementHandle<Element> add_element(MultibodySystem& system, std::unique_ptr<Element> element) {
  const ElementHandle<Element> handle{element.get(), system.force_elements().size()};
  system.add_force_element(std::move(element));
  return handle;
}

}  // namespace heavesim
