#pragma once
// The output channels of a control element as a table of (channel, field of the
// element's state struct): described once, filled without allocation.
#include <span>
#include <string>
#include <vector>

#include "kernel/elements/force_element.hpp"

namespace heavesim {

template <class State>
class ChannelTable {
 public:
  void add(std::string name, std::string units, std::string description, double State::*field) {
    channels_.push_back({std::move(name), std::move(units), std::move(description)});
    fields_.push_back(field);
  }
  const std::vector<ElementChannel>& channels() const { return channels_; }
  void fill(const State& state, std::span<double> values) const {
    for (std::size_t k = 0; k < fields_.size(); ++k) values[k] = state.*fields_[k];
  }

 private:
  std::vector<ElementChannel> channels_;
  std::vector<double State::*> fields_;
};

}  // namespace heavesim
