// OMPL peer benchmark: OMPL's planners on any box-world problem `mit-star` can write
// (`mit-star problems --write NAME --dim N [--instance K] > P.toml`), with our box semantics
// and check resolution. Records time to the first exact solution, validity calls up to it,
// total solve time, and the isolated cost of one validity call.
//
// Build (OMPL 2.x from source, or Debian's 1.5; EIT* needs OMPL >= 1.6):
//   g++ -std=c++17 -O2 -I$OMPL/include/ompl-2.0 -I/usr/include/eigen3 driver.cpp -o driver \
//       -L$OMPL/lib -lompl -Wl,-rpath,$OMPL/lib -lpthread
// Run:    ./driver run P.toml EITstar SEED [BUDGET_S]   (one CSV line)
//         ./driver iso P.toml                           (ns per validity call)
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/goals/GoalStates.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/config.h>
#include <ompl/geometric/planners/informedtrees/AITstar.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/rrt/InformedRRTstar.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>
#if OMPL_MAJOR_VERSION >= 2 || OMPL_MINOR_VERSION >= 6
#include <ompl/geometric/planners/informedtrees/EITstar.h>
#define PEER_HAS_EIT 1
#endif

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace ob = ompl::base;
namespace og = ompl::geometric;
using Clock = std::chrono::steady_clock;

// A box as mit-star's `AxisBox`: closed membership |x_d - c_d| <= w_d / 2 + DBL_EPSILON.
struct Box {
    std::vector<double> center, half;
    bool contains(const double *x) const {
        for (size_t d = 0; d < center.size(); ++d)
            if (std::fabs(x[d] - center[d]) > half[d]) return false;
        return true;
    }
};

// A problem file as `mit-star problems --write` prints it (the subset used by box worlds:
// name, resolution, start, goal(s), bounds, obstacles, anti-obstacles; no lattices).
struct World {
    std::string name;
    double resolution = 5e-6;
    size_t n = 0;
    std::vector<double> lower, upper, start;
    std::vector<std::vector<double>> goals;
    std::vector<Box> obstacles, antis;
    bool valid(const double *x) const {
        for (size_t d = 0; d < n; ++d)
            if (x[d] < lower[d] || x[d] > upper[d]) return false;
        for (const auto &o : obstacles)
            if (o.contains(x)) {
                for (const auto &a : antis)
                    if (a.contains(x)) return true;
                return false;
            }
        return true;
    }
};

static std::vector<double> numbers(const std::string &text) {
    std::vector<double> out;
    std::string s = text;
    for (char &c : s)
        if (c == '[' || c == ']' || c == ',') c = ' ';
    std::istringstream in(s);
    double v;
    while (in >> v) out.push_back(v);
    return out;
}

static void fail(const std::string &what) {
    std::fprintf(stderr, "driver: %s\n", what.c_str());
    std::exit(2);
}

World readWorld(const std::string &path) {
    std::ifstream file(path);
    if (!file) fail("cannot read " + path);
    World w;
    std::string line, table;
    std::vector<double> center;
    while (std::getline(file, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (line[0] == '[') {
            table = line;
            if (line.find("lattice") != std::string::npos) fail(path + ": lattices are not supported");
            continue;
        }
        auto eq = line.find('=');
        if (eq == std::string::npos) continue;
        std::string key = line.substr(0, eq), value = line.substr(eq + 1);
        key.erase(key.find_last_not_of(' ') + 1);
        if (key == "name") {
            auto a = value.find('"'), b = value.rfind('"');
            w.name = value.substr(a + 1, b - a - 1);
        } else if (key == "resolution") {
            w.resolution = std::stod(value);
        } else if (key == "start") {
            w.start = numbers(value);
        } else if (key == "goal") {
            w.goals.push_back(numbers(value));
        } else if (key == "goals") {
            // [[a, b], [c, d]]: split on "], ["
            std::string s = value;
            size_t at = 0;
            while ((at = s.find(']', at)) != std::string::npos) {
                size_t open = s.rfind('[', at);
                auto g = numbers(s.substr(open, at - open + 1));
                if (!g.empty()) w.goals.push_back(g);
                ++at;
            }
        } else if (key == "lower") {
            w.lower = numbers(value);
        } else if (key == "upper") {
            w.upper = numbers(value);
        } else if (key == "center") {
            center = numbers(value);
        } else if (key == "widths") {
            Box b;
            b.center = center;
            for (double x : numbers(value)) b.half.push_back(0.5 * x + DBL_EPSILON);
            (table == "[[obstacles]]" ? w.obstacles : w.antis).push_back(b);
        }
    }
    w.n = w.start.size();
    if (w.n == 0 || w.lower.size() != w.n || w.upper.size() != w.n || w.goals.empty())
        fail(path + ": missing start, goal or bounds");
    return w;
}

class Checker : public ob::StateValidityChecker {
public:
    Checker(const ob::SpaceInformationPtr &si, const World &w) : ob::StateValidityChecker(si), w_(w) {}
    bool isValid(const ob::State *s) const override {
        ++calls;
        return w_.valid(s->as<ob::RealVectorStateSpace::StateType>()->values);
    }
    mutable unsigned long long calls = 0;

private:
    const World &w_;
};

struct Setup {
    ob::SpaceInformationPtr si;
    std::shared_ptr<Checker> checker;
    ob::ProblemDefinitionPtr pdef;
};

Setup makeSetup(const World &w) {
    auto space = std::make_shared<ob::RealVectorStateSpace>(w.n);
    ob::RealVectorBounds bounds(w.n);
    bounds.low = w.lower;
    bounds.high = w.upper;
    space->setBounds(bounds);
    Setup s;
    s.si = std::make_shared<ob::SpaceInformation>(space);
    s.checker = std::make_shared<Checker>(s.si, w);
    s.si->setStateValidityChecker(s.checker);
    s.si->setStateValidityCheckingResolution(w.resolution);
    s.si->setup();
    s.pdef = std::make_shared<ob::ProblemDefinition>(s.si);
    ob::ScopedState<> start(space);
    for (size_t d = 0; d < w.n; ++d) start[d] = w.start[d];
    s.pdef->addStartState(start);
    auto goals = std::make_shared<ob::GoalStates>(s.si);  // threshold: machine epsilon
    for (const auto &g : w.goals) {
        ob::ScopedState<> goal(space);
        for (size_t d = 0; d < w.n; ++d) goal[d] = g[d];
        goals->addState(goal);
    }
    s.pdef->setGoal(goals);
    s.pdef->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(s.si));
    return s;
}

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

// The paper's range for the RRT family (mit-star's `default_range`): 0.3, 0.5, 1.25 and 3.0
// in R^2, R^4, R^8 and R^16, else a fifth of the maximum extent.
double paperRange(const ob::SpaceInformationPtr &si) {
    switch (si->getStateDimension()) {
        case 2: return 0.3;
        case 4: return 0.5;
        case 8: return 1.25;
        case 16: return 3.0;
        default: return 0.2 * si->getMaximumExtent();
    }
}

// mit-star's defaults where a planner has them: 100 samples per batch, rewire/radius factor
// 1.001 and k-nearest for the informed trees; the paper's range for RRT-Connect and Informed
// RRT*, which also gets rewire factor 1.2, k-nearest and 5 % goal bias.
ob::PlannerPtr makePlanner(const std::string &name, const ob::SpaceInformationPtr &si) {
#ifdef PEER_HAS_EIT
    if (name == "EITstar") {
        auto p = std::make_shared<og::EITstar>(si);
        p->setBatchSize(100);
        p->setRadiusFactor(1.001);
        p->setUseKNearest(true);
        return p;
    }
#endif
    if (name == "AITstar") {
        auto p = std::make_shared<og::AITstar>(si);
        p->setBatchSize(100);
        p->setRewireFactor(1.001);
        p->setUseKNearest(true);
        return p;
    }
    if (name == "BITstar") {
        auto p = std::make_shared<og::BITstar>(si);
        p->setSamplesPerBatch(100);
        p->setRewireFactor(1.001);
        p->setUseKNearest(true);
        p->setStopOnSolnImprovement(true);
        return p;
    }
    if (name == "InformedRRTstar") {
        auto p = std::make_shared<og::InformedRRTstar>(si);
        p->setRange(paperRange(si));
        p->setRewireFactor(1.2);
        p->setKNearest(true);
        p->setGoalBias(0.05);
        return p;
    }
    if (name == "RRTConnect") {
        auto p = std::make_shared<og::RRTConnect>(si);
        p->setRange(paperRange(si));
        return p;
    }
    fail("unknown planner " + name);
    return nullptr;
}

// One run (one process per run: RNG::setSeed works only before the first RNG exists).
void runOnce(const World &w, const std::string &planner, unsigned seed, double budget) {
    Setup s = makeSetup(w);
    ob::PlannerPtr p = makePlanner(planner, s.si);
    p->setProblemDefinition(s.pdef);
    auto ts = Clock::now();
    p->setup();
    double setupMs = ms(Clock::now() - ts);
    s.checker->calls = 0;
    bool gotCb = false;
    double cbMs = NAN;
    unsigned long long cbCalls = 0;
    Clock::time_point t0;
    s.pdef->setIntermediateSolutionCallback(
        [&](const ob::Planner *, const std::vector<const ob::State *> &, const ob::Cost) {
            if (!gotCb) {
                gotCb = true;
                cbMs = ms(Clock::now() - t0);
                cbCalls = s.checker->calls;
            }
        });
    auto ptc = ob::plannerOrTerminationCondition(ob::exactSolnPlannerTerminationCondition(s.pdef),
                                                 ob::timedPlannerTerminationCondition(budget));
    t0 = Clock::now();
    ob::PlannerStatus st = p->solve(ptc);
    double total = ms(Clock::now() - t0);
    unsigned long long calls = s.checker->calls;
    bool ok = st == ob::PlannerStatus::EXACT_SOLUTION && s.pdef->hasExactSolution();
    // Planners without the callback (RRT-Connect) stop at their first solution anyway.
    double first = gotCb ? cbMs : total;
    unsigned long long firstCalls = gotCb ? cbCalls : calls;
    double cost = ok ? s.pdef->getSolutionPath()->length() : NAN;
    // problem,planner,seed,exact,callback,t_first_ms,calls_first,t_total_ms,calls_total,cost,setup_ms
    std::printf("%s,%zu,%s,%u,%d,%d,%.4f,%llu,%.4f,%llu,%.6f,%.4f\n", w.name.c_str(), w.n, planner.c_str(),
                seed, ok, gotCb, first, firstCalls, total, calls, cost, setupMs);
}

// The cost of one validity call as a motion validator makes it: states interpolated along
// random fully valid segments of length 0.3 at the problem's resolution, through
// SpaceInformation::isValid; a second pass without the call is subtracted.
void isolated(const World &w, unsigned long long total) {
    Setup s = makeSetup(w);
    auto space = s.si->getStateSpace();
    const size_t n = w.n;
    std::mt19937_64 rng(42);
    std::normal_distribution<double> G(0, 1);
    const double len = 0.3;
    const unsigned steps = (unsigned)std::ceil(len / (w.resolution * space->getMaximumExtent()));
    std::vector<std::pair<std::vector<double>, std::vector<double>>> segs;
    std::vector<double> x(n);
    auto segValid = [&](const std::vector<double> &a, const std::vector<double> &b) {
        for (unsigned j = 0; j <= steps; ++j) {
            double t = double(j) / steps;
            for (size_t d = 0; d < n; ++d) x[d] = a[d] + t * (b[d] - a[d]);
            if (!w.valid(x.data())) return false;
        }
        return true;
    };
    for (size_t tries = 0; segs.size() < 200 && tries < 200000; ++tries) {
        std::vector<double> a(n), b(n), dir(n);
        double nn = 0;
        for (size_t d = 0; d < n; ++d) {
            a[d] = std::uniform_real_distribution<double>(w.lower[d], w.upper[d])(rng);
            dir[d] = G(rng);
            nn += dir[d] * dir[d];
        }
        nn = std::sqrt(nn);
        for (size_t d = 0; d < n; ++d) b[d] = a[d] + len * dir[d] / nn;
        if (segValid(a, b)) segs.emplace_back(a, b);
    }
    if (segs.empty()) fail(w.name + ": no fully valid segment found");
    ob::State *sa = space->allocState(), *sb = space->allocState(), *si = space->allocState();
    auto load = [&](ob::State *st, const std::vector<double> &v) {
        for (size_t d = 0; d < n; ++d) st->as<ob::RealVectorStateSpace::StateType>()->values[d] = v[d];
    };
    double perCall[2] = {0, 0};
    for (int pass = 0; pass < 2; ++pass) {
        unsigned long long done = 0, nvalid = 0;
        double sink = 0;
        size_t k = 0;
        auto t0 = Clock::now();
        while (done < total) {
            const auto &sg = segs[k++ % segs.size()];
            load(sa, sg.first);
            load(sb, sg.second);
            for (unsigned j = 1; j < steps && done < total; ++j, ++done) {
                space->interpolate(sa, sb, double(j) / steps, si);
                if (pass == 0)
                    nvalid += s.si->isValid(si);
                else
                    sink += si->as<ob::RealVectorStateSpace::StateType>()->values[0];
            }
        }
        perCall[pass] = 1e6 * ms(Clock::now() - t0) / double(total);
        if (pass == 0 && nvalid != total) fail("a state on a valid segment was invalid");
        if (sink == 12345.678) std::printf(" ");
    }
    std::printf("%s R^%zu: interpolate + isValid %.1f ns, interpolate alone %.1f ns, isValid %.1f ns per call "
                "(%zu valid segments of length %.2f, %u steps each)\n",
                w.name.c_str(), n, perCall[0], perCall[1], perCall[0] - perCall[1], segs.size(), len, steps);
    space->freeState(sa);
    space->freeState(sb);
    space->freeState(si);
}

int main(int argc, char **argv) {
    std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "run" && (argc == 5 || argc == 6)) {
        ompl::RNG::setSeed((unsigned)std::stoul(argv[4]));  // before any RNG exists
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        World w = readWorld(argv[2]);
        if (!w.valid(w.start.data())) fail(w.name + ": invalid start");
        runOnce(w, argv[3], (unsigned)std::stoul(argv[4]), argc == 6 ? std::stod(argv[5]) : 3.0);
        return 0;
    }
    if (mode == "iso" && argc == 3) {
        ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
        isolated(readWorld(argv[2]), 10000000ULL);
        return 0;
    }
    std::fprintf(stderr,
                 "usage: driver run PROBLEM.toml EITstar|AITstar|BITstar|InformedRRTstar|RRTConnect SEED [BUDGET_S]\n"
                 "       driver iso PROBLEM.toml\n");
    return 2;
}
