#include <cmath>
#include <core/Scene.hpp>
#include <pkg/dem/concrete/UniaxialStrainer.hpp>
#include <stdexcept>
#include <string>

namespace yade {

Real UniaxialStrainer::length() const {
    const BodyStore::Columns c = scene->bodies.hot().columns();
    return c.pos[posIds[0]][axis] - c.pos[negIds[0]][axis];
}

void UniaxialStrainer::init() {
    const auto fail = [](const std::string& what) { throw std::invalid_argument("UniaxialStrainer: " + what); };
    if (axis < 0 || axis > 2) fail("axis must be 0, 1 or 2, got " + std::to_string(axis));
    if (asymmetry < -1 || asymmetry > 1) fail("asymmetry must be -1, 0 or 1, got " + std::to_string(asymmetry));
    if (posIds.empty() || negIds.empty()) fail("posIds and negIds must both name bodies");
    for (const auto* ids : {&posIds, &negIds})
        for (int id : *ids)
            if (!scene->bodies.exists(id)) fail("body #" + std::to_string(id) + " of posIds/negIds does not exist");
    if (!(crossSectionArea > 0 && std::isfinite(crossSectionArea))) fail("crossSectionArea must be given (positive), got " + std::to_string(crossSectionArea));
    const Real L = length();
    if (!(L > 0))
        fail("body #" + std::to_string(posIds[0]) + " (posIds[0]) must be further along the axis than #" + std::to_string(negIds[0]) + " (negIds[0])");
    if (std::isnan(strainRate)) {
        if (!std::isfinite(absSpeed)) fail("strainRate or absSpeed must be given");
        strainRate = absSpeed / L;
    } else {
        if (!std::isfinite(strainRate)) fail("strainRate must be finite");
        absSpeed = strainRate * L;
    }
    int mask = blockDisplacements ? State::DOF_X | State::DOF_Y | State::DOF_Z : 1 << axis;
    if (blockRotations) mask |= State::DOF_RX | State::DOF_RY | State::DOF_RZ;
    BodyStore::Columns c = scene->bodies.hot().columns();
    for (const auto* ids : {&posIds, &negIds})
        for (int id : *ids) c.blockedDOFsMask[id] = mask | (c.blockedDOFsMask[id] & State::clumpedBit);
    currentStrainRate = strainRate;
    originalLength = L;
    if (setSpeeds) { // every body gets the velocity of the uniform strain field, the ends' included
        const Real x0 = c.pos[negIds[0]][axis], vNeg = asymmetry == 0 ? -absSpeed / 2 : asymmetry > 0 ? 0 : -absSpeed;
        for (size_t id = 0; id < scene->bodies.size(); ++id)
            if (scene->bodies.exists((Body::id_t)id)) c.vel[id][axis] = vNeg + strainRate * (c.pos[id][axis] - x0);
    }
}

void UniaxialStrainer::moveEnds(Real speed) {
    BodyStore::Columns c = scene->bodies.hot().columns();
    const Real pos = asymmetry == 0 ? speed / 2 : asymmetry > 0 ? speed : 0;
    const Real neg = asymmetry == 0 ? -speed / 2 : asymmetry < 0 ? -speed : 0;
    for (int id : posIds) c.vel[id][axis] = pos;
    for (int id : negIds) c.vel[id][axis] = neg;
}

void UniaxialStrainer::action() {
    if (std::isnan(originalLength)) init(); // (a loaded scene keeps its originalLength: no second start)
    const Real dt = scene->dt;
    const Real current = length();
    strain = current / originalLength - 1;
    if (idleLeft >= 0 && idleLeft-- == 0) scene->stopAtIter = scene->iter + 1; // (pauses after this step)
    if (active) {
        if (limitStrain != 0 && notYetReversed && (limitStrain > 0 ? strain >= limitStrain : strain <= limitStrain)) {
            strainRate = -strainRate; // reversed once
            absSpeed = -absSpeed;
            notYetReversed = false;
        }
        currentStrainRate = strainRate;
        Real speed = currentStrainRate * originalLength;
        if (!std::isnan(stopStrain) && std::abs(strain + currentStrainRate * dt) > std::abs(stopStrain)) {
            speed = ((1 + stopStrain) * originalLength - current) / dt; // this step lands on stopStrain
            active = false;
            idleLeft = idleIterations;
        }
        moveEnds(speed);
    } else if (idleLeft < 0) {
        moveEnds(0);
    }
    if (stressUpdateInterval > 0 && scene->iter % stressUpdateInterval == 0) {
        Real sumPos = 0, sumNeg = 0;
        for (int id : posIds) sumPos += scene->forces.getForce(id)[axis];
        for (int id : negIds) sumNeg += scene->forces.getForce(id)[axis];
        avgStress = (sumNeg - sumPos) / (2 * crossSectionArea);
    }
}

} // namespace yade
