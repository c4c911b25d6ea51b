// Part 3 of the class registration (pkg/RegisterClasses.hpp).
#define YADE_REGISTRATION_PART 3
#include <pkg/RegisterClassesPart.ipp>
