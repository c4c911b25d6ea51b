// Part 2 of the class registration (pkg/RegisterClasses.hpp).
#define YADE_REGISTRATION_PART 2
#include <pkg/RegisterClassesPart.ipp>
