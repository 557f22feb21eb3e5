#pragma once
// Stand-in for Pinocchio's generated deprecation header (see config.hpp here).
#define PINOCCHIO_DEPRECATED [[deprecated]]
#define PINOCCHIO_DEPRECATED_MESSAGE(message) [[deprecated(message)]]
