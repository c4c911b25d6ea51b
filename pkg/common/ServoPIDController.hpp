// A TranslationEngine whose velocity along `axis` is set by a PID controller so that the force
// on the bodies along that axis reaches `target`: every iterPeriod steps
//   error = |F·axis| - target,  iTerm += kI·error,  curVel = kP·error + iTerm + kD·(error - previous error),
// clamped to |curVel| <= maxVelocity.
#pragma once
#include <pkg/common/TranslationEngine.hpp>

namespace yade {

class ServoPIDController : public TranslationEngine {
public:
    static constexpr const char* classDoc = "PID servo: translates the bodies in ids along axis with a velocity that drives the magnitude of their total force along axis to target; every iterPeriod steps error = |F·axis| - target, iTerm += kI·error, curVel = kP·error + iTerm + kD·(error - errorPrev), limited to ±maxVelocity.";
    Real maxVelocity = 0;
    Vector3r axis = Vector3r::Zero();
    Real target = 0;
    Vector3r current = Vector3r::Zero();
    Real kP = 0, kI = 0, kD = 0;
    Real iTerm = 0, curVel = 0, errorCur = 0, errorPrev = 0;
    long long iterPeriod = 100, iterPrevStart = -1;
    template <class V> void visit(V& v) {
        TranslationEngine::visit(v);
        v.attr("maxVelocity", maxVelocity, "Largest magnitude of the applied velocity [m/s]", Attr::nonNegative);
        v.attr("axis", axis, "Direction along which the velocity is applied and the force measured (normalized when used)", Attr::finite);
        v.attr("target", target, "Target value of the force magnitude along axis [N]", Attr::finite);
        v.attr("current", current, "Total force on the bodies projected on axis, at the last update [N]");
        v.attr("kP", kP, "Proportional gain [m/(N·s)]", Attr::finite);
        v.attr("kI", kI, "Integral gain (the integral term is a sum over updates, without time) [m/(N·s)]", Attr::finite);
        v.attr("kD", kD, "Derivative gain (the difference of errors between updates) [m/(N·s)]", Attr::finite);
        v.attr("iTerm", iTerm, "Integral term [m/s]");
        v.attr("curVel", curVel, "Velocity applied now [m/s]");
        v.attr("errorCur", errorCur, "Error at the last update [N]");
        v.attr("errorPrev", errorPrev, "Error at the update before (equal to errorCur once the update is done) [N]");
        v.attr("iterPeriod", iterPeriod, "The controller updates the velocity every this many steps", Attr::positive);
        v.attr("iterPrevStart", iterPrevStart, "Step of the last update (-1: none yet)");
    }
    void apply(const std::vector<int>& bodyIds) override;
};

} // namespace yade
