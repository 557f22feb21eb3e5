#pragma once
// Stand-in for Pinocchio's generated warning header (see config.hpp here).
#define PINOCCHIO_WARNING_PUSH _Pragma("GCC diagnostic push")
#define PINOCCHIO_WARNING_POP _Pragma("GCC diagnostic pop")
