#include <pkg/dem/ViscElPhys.hpp>
#include <sstream>

namespace yade {

std::string ViscElPhys::diagnoseSpin() const {
    if (!(mR > 0)) return std::string();
    std::ostringstream os;
    os.precision(3);
    os << "the rolling resistance of its contacts (ViscElPhys.mR=" << mR << ", mRtype=" << mRtype
       << "): its torque is mR·|Fn| times the relative spin (mRtype 2: also times the spin's speed at the contact), "
       << "stable only while O.dt·mR·|Fn| (mRtype 2: ·|Δ(ω×arm)|) stays below about twice the body's moment of inertia; "
       << "use a smaller O.dt or mR";
    return os.str();
}

} // namespace yade
