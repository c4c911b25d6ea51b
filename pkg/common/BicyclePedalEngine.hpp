// Bodies moved along circles around an axis without turning (the motion of a bicycle pedal).
#pragma once
#include <pkg/common/KinematicEngine.hpp>

namespace yade {

class BicyclePedalEngine : public KinematicEngine {
public:
    static constexpr const char* classDoc =
            "Kinematic engine moving the bodies in ids along circles of the given radius in the plane normal to rotationAxis, "
            "each around its own centre and without turning them (a bicycle pedal): the velocity is the displacement of the "
            "point radius·(-cos fi, -sin fi) (in the plane's axes, those of z turned onto rotationAxis) over the step, and fi "
            "grows by angularVelocity·dt every step.";
    Real angularVelocity = 0, radius = -1, fi = Mathr_PI / 2;
    Vector3r rotationAxis = Vector3r::UnitX();
    template <class V> void visit(V& v) {
        KinematicEngine::visit(v);
        v.attr("angularVelocity", angularVelocity, "Angular velocity along the circle [rad/s]", Attr::finite);
        v.attr("rotationAxis", rotationAxis, "Normal of the circles' plane (normalized when the engine runs)", Attr::finite);
        v.attr("radius", radius, "Radius of the circles [m]", Attr::finite);
        v.attr("fi", fi, "Current angle along the circle [rad]", Attr::finite);
    }
    void apply(const std::vector<int>& bodyIds) override;
};

} // namespace yade
