#pragma once
// The range of each kind of quantity a case may give, stated once. Derived quantities
// (a body's inertia about a joint, m r^2; a spring force, k x; a moment, F r) are
// products of a few inputs: the ranges keep such products finite and meaningful in
// double precision, and they are wide enough for any offshore structure in SI units.
#include <string_view>

namespace heavesim {

struct QuantityRange {
  std::string_view kind;  // "a length", ...: names the range in messages
  double lower, upper;    // inclusive
  std::string_view unit;
};

/// Any number of a case: products of up to twenty such numbers stay below the double
/// range (1.8e308), and 1e15 exceeds every SI quantity a case needs (the stiffest
/// contact in cases/ is 1e12 N/m). NaN and infinity are never a value.
inline constexpr QuantityRange any_number{"a finite number", -1e15, 1e15, ""};

/// Positions, offsets and lengths [m]: 1000 km is beyond any rig, mooring or vessel,
/// and at 1e6 m a double still resolves 2e-10 m, below the default constraint
/// tolerance (1e-10 m) and the assembly's accuracy.
inline constexpr QuantityRange length_range{"a length", -1e6, 1e6, "m"};

/// Body masses [kg]: the heaviest floating structures are below 1e9 kg; with lengths
/// below 1e6 m, m r^2 stays below 1e22 kg m^2.
inline constexpr QuantityRange mass_range{"a mass", 0.0, 1e10, "kg"};

/// Moments of inertia [kg m^2]: the largest mass at 1e4 m from its centre.
inline constexpr QuantityRange inertia_range{"a moment of inertia", -1e18, 1e18, "kg m^2"};

}  // namespace heavesim
