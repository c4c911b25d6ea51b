#include <core/Scene.hpp>
#include <atomic>
#include <chrono>
#include <cmath>
#include <ctime>
#include <algorithm>
#include <pwd.h>
#include <random>
#include <stdexcept>
#include <unistd.h>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace yade {

// The end of a step: iter and time advance. Python may read O.iter and O.time while the loop thread
// does this (a script waiting for a background run): relaxed atomic stores, as the reads, so that the
// two threads do not race (plain moves on x86-64; a data race is undefined behaviour).
static void advanceClock(Scene& s) {
    __atomic_store_n(&s.iter, s.iter + 1, __ATOMIC_RELAXED);
    Real t = s.time + s.dt;
    __atomic_store(&s.time, &t, __ATOMIC_RELAXED);
}

static std::string nowString(const char* fmt) {
    std::time_t t = std::time(nullptr);
    char buf[64];
    std::strftime(buf, sizeof buf, fmt, std::localtime(&t));
    return buf;
}

bool Scene::timingEnabled = false;

static std::atomic<long long> sceneCount{0};

// "Full Name (user@host)" with the spaces as '~', as the reference's O.tags['author'] ("root~(root@vm)").
static std::string authorTag() {
    std::string user = "unknown", name;
    if (const passwd* pw = getpwuid(getuid())) {
        user = pw->pw_name;
        name = pw->pw_gecos ? std::string(pw->pw_gecos).substr(0, std::string(pw->pw_gecos).find(',')) : "";
    }
    char host[256] = "";
    if (gethostname(host, sizeof host - 1) != 0) host[0] = 0;
    std::string tag = (name.empty() ? user : name) + " (" + user + "@" + host + ")";
    std::replace(tag.begin(), tag.end(), ' ', '~');
    return tag;
}

Scene::Scene() : serial(++sceneCount) {
    // id: unique per run (time, pid-like random suffix); d.id adds a description later.
    std::random_device rd;
    char suffix[16];
    std::snprintf(suffix, sizeof suffix, "p%05u", rd() % 100000);
    tags["id"] = nowString("%Y%m%dT%H%M%S") + suffix;
    tags["d.id"] = tags["id"];
    tags["id.d"] = tags["id"];
    tags["description"] = "";
    tags["isoTime"] = nowString("%Y%m%dT%H%M%S");
    tags["author"] = authorTag();
#ifdef _OPENMP
    setThreads(omp_get_max_threads());
#endif
}

void Scene::setThreads(int n) {
    forces.setThreads(n);
    energy.setThreads(n);
}

void Scene::setPeriodic(bool periodic) {
    if (periodic == isPeriodic) return;
    isPeriodic = periodic;
    interactions.setPeriodic(periodic); // (the pairs' cellDist: kept only in a periodic scene)
}

Matrix3r Scene::flipCell(Matrix3r flip) {
    if (!isPeriodic) throw std::invalid_argument("flipCell: the scene is not periodic (O.periodic=False)");
    Cell& c = *cell;
    if (flip == Matrix3r::Zero()) // each edge j less the whole multiples of the others its projections hold
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i)
                if (i != j) flip(i, j) = -std::round(c.hSize.col(i).dot(c.hSize.col(j)) / c.hSize.col(i).squaredNorm());
    const Matrix3r m = Matrix3r::Identity() + flip;
    if (!(m.array() == m.array().round()).all() || std::abs(m.determinant() - 1) > 1e-9)
        throw std::invalid_argument("flipCell: I + flip must be an integer matrix of determinant 1 (a cell of the same lattice)");
    if (flip == Matrix3r::Zero()) return flip;
    c.hSize = c.hSize * m;
    c.prevHSize = c.prevHSize * m;
    // images at hSize·c = hSize'·c' with hSize' = hSize·m: c' = m⁻¹·c (integer: m is unimodular)
    const Matrix3r inv = m.inverse();
    for (Vector3i& d : interactions.cellDist) d = (inv * d.cast<Real>()).array().round().cast<int>().matrix();
    ++bodies.changes;       // (the collider starts afresh)
    ++interactions.changes; // (and the interaction loop: the pairs' images changed)
    return flip;
}

void Scene::setDt(Real value) {
    // (0 is accepted, as in the reference: steps that advance nothing, e.g. to create contacts in place)
    if (!std::isfinite(value) || value < 0)
        throw std::invalid_argument("O.dt must be finite and not negative (got " + std::to_string(value) + ")");
    dt = value;
}

void Scene::setEngines(const std::vector<std::shared_ptr<Engine>>& e) {
    for (const auto& x : e)
        if (!x) throw std::invalid_argument("O.engines: None is not an engine");
    std::lock_guard<std::mutex> lock(enginesMutex);
    if (inStep) {
        nextEngines = e;
        hasNextEngines = true;
    } else {
        engines = e;
    }
}

// A body whose state Python set to None stops the step before it begins, naming the body, as in
// the reference (which says so for a body with a material; without one it fails too, at random).
static void checkStates(const BodyContainer& bodies) {
    if (Body::standInsAlive() == 0) return;
    for (const auto& b : bodies)
        if (b && b->stateIsNone())
            throw std::runtime_error("Body #" + std::to_string(b->id) + (b->material ? ": has Body::material, but NULL Body::state." : ": has NULL Body::state."));
}

void Scene::beginStep() {
    checkStates(bodies);
    {
        std::lock_guard<std::mutex> lock(enginesMutex);
        inStep = true;
    }
    forces.resize(bodies.size());
    interactions.resizeBodies(bodies.size());
    interactions.iterNow = iter;
    if (trackEnergy) energy.resetInstantaneous();
    if (isPeriodic) cell->integrate(dt);
    newContacts.clear();
    failedEngine.clear();
}

void Scene::runEngine(Engine& e) {
    e.scene = this;
    failedEngine.clear();
    try {
        if (e.dead || !e.isActivated()) return;
        runEngineAction(e);
    } catch (...) {
        if (failedEngine.empty()) // (not set by an engine this one ran)
            failedEngine = e.getClassName() + (e.label.empty() ? std::string() : " labeled '" + e.label + "'");
        throw;
    }
}

void Scene::runEngineAction(Engine& e) {
    if (!timingEnabled) {
        e.action();
        return;
    }
    const auto t0 = std::chrono::steady_clock::now();
    e.action();
    e.execTime += std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
    ++e.execCount;
}

void Scene::leaveStep() {
    std::lock_guard<std::mutex> lock(enginesMutex);
    inStep = false;
    if (hasNextEngines) {
        engines = std::move(nextEngines);
        nextEngines.clear();
        hasNextEngines = false;
    }
}

void Scene::moveToNextTimeStep() {
    if (subStep >= 0) { // a step begun by sub-steps: run its remaining parts
        while (subStep >= 0) moveToNextSubStep();
        return;
    }
    struct StepEnd { // (also when an engine throws)
        Scene& s;
        ~StepEnd() {
            s.subStep = -1;
            s.leaveStep();
        }
    } stepEnd{*this};
    beginStep();
    subStep = 0; // (what O.subStep reads inside a whole step)
    const auto running = engines; // engines may be replaced from inside a step
    for (const auto& e : running) runEngine(*e);
    advanceClock(*this);
}

void Scene::moveToNextSubStep() {
    if (subStep < 0) {
        beginStep();
        subStep = 0;
        return;
    }
    if (subStep < (int)engines.size()) {
        const std::shared_ptr<Engine> e = engines[subStep++]; // (moves on even if it throws)
        runEngine(*e);
        return;
    }
    subStep = -1;
    leaveStep();
    advanceClock(*this);
}

Body::id_t Scene::appendBody(const std::shared_ptr<Body>& b) {
    const Body::id_t id = bodies.insert(b);
    b->iterBorn = iter;
    b->timeBorn = time;
    forces.resize(bodies.size());
    interactions.resizeBodies(bodies.size());
    return id;
}

void Scene::eraseBody(Body::id_t id) {
    if (!bodies.exists(id)) throw std::out_of_range("Body #" + std::to_string(id) + " does not exist.");
    interactions.eraseBody(id);
    bodies.erase(id);
}

int Scene::appendMaterial(const std::shared_ptr<Material>& m) {
    if (!m) throw std::invalid_argument("cannot append None to O.materials");
    if (m->id >= 0) throw std::invalid_argument("Material already has id " + std::to_string(m->id) + "; appending it twice is not allowed.");
    m->id = (int)materials.size();
    materials.push_back(m);
    return m->id;
}

} // namespace yade
