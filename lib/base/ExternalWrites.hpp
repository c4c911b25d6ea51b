// Writes made to simulation objects from outside the engines: attribute setters and in-place
// changes of vectors, quaternions and matrices from Python. An engine that keeps data derived from
// bodies (positions, shapes) from one step to the next may use it while this count and O.bodies'
// change counter are unchanged: then only engines have changed the scene since.
#pragma once

namespace yade {

long long externalWrites();
void noteExternalWrite();

} // namespace yade
