// Part 1 of the class registration (pkg/RegisterClasses.hpp).
#define YADE_REGISTRATION_PART 1
#include <pkg/RegisterClassesPart.ipp>
