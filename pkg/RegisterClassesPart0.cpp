// Part 0 of the class registration (pkg/RegisterClasses.hpp).
#define YADE_REGISTRATION_PART 0
#include <pkg/RegisterClassesPart.ipp>
