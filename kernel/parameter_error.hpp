#pragma once
// A parameter a domain function cannot work with: the one vocabulary in which kernel/,
// hydro/ and control/ state their rules on their inputs. Each rule is stated once, in
// the domain code that needs it; the application maps `field` to the case key it came
// from (app/case/case_definition.hpp, CaseDefinition::keyed_error) and reports it as
// bad input (exit code 2) at that key's file position.
#include <stdexcept>
#include <string>

namespace heavesim {

class ParameterError : public std::runtime_error {
 public:
  /// field: the parameter's name in the domain (e.g. "kernel_step", "max_rate");
  /// found: what was given, with its value; expected: what the function needs.
  ParameterError(std::string field, std::string found, std::string expected)
      : std::runtime_error(field + ": found " + found + "; expected " + expected),
        field_(std::move(field)),
        found_(std::move(found)),
        expected_(std::move(expected)) {}

  const std::string& field() const { return field_; }
  const std::string& found() const { return found_; }
  const std::string& expected() const { return expected_; }

 private:
  std::string field_, found_, expected_;
};

}  // namespace heavesim
