#pragma once
// Stand-in for the header Pinocchio's CMake configuration generates (it is absent from
// a source tree). The side-by-side benchmark uses Pinocchio header-only: no shared
// library, so the export macros are empty and no template is instantiated explicitly.
#define PINOCCHIO_MAJOR_VERSION 3
#define PINOCCHIO_MINOR_VERSION 7
#define PINOCCHIO_PATCH_VERSION 0
#define PINOCCHIO_VERSION "3.7.0"
#define PINOCCHIO_VERSION_AT_LEAST(major, minor, patch)                                      \
  (PINOCCHIO_MAJOR_VERSION > (major) ||                                                     \
   (PINOCCHIO_MAJOR_VERSION == (major) &&                                                   \
    (PINOCCHIO_MINOR_VERSION > (minor) ||                                                   \
     (PINOCCHIO_MINOR_VERSION == (minor) && PINOCCHIO_PATCH_VERSION >= (patch)))))
#define PINOCCHIO_DLLAPI
#define PINOCCHIO_LOCAL
#define PINOCCHIO_EXPLICIT_INSTANTIATION_DECLARATION_DLLAPI
#define PINOCCHIO_EXPLICIT_INSTANTIATION_DEFINITION_DLLAPI
