// OMPL peer benchmark: BIT* and RRT-Connect on PDT's dividing walls (DW) and goal
// enclosure (GE) in R^4. Records time to first exact solution, validity calls up to it,
// total solve time, and the isolated cost of one validity check.
//
// Build: g++ -std=c++17 -O2 -I/usr/include/ompl-1.5 -I/usr/include/eigen3 driver.cpp -o driver -lompl -lpthread
// Run:   ./run.sh && python3 summary.py && cat iso.txt
#include <ompl/base/ProblemDefinition.h>
#include <ompl/base/SpaceInformation.h>
#include <ompl/base/StateValidityChecker.h>
#include <ompl/base/goals/GoalState.h>
#include <ompl/base/objectives/PathLengthOptimizationObjective.h>
#include <ompl/base/spaces/RealVectorStateSpace.h>
#include <ompl/geometric/planners/informedtrees/BITstar.h>
#include <ompl/geometric/planners/rrt/RRTConnect.h>
#include <ompl/util/Console.h>
#include <ompl/util/RandomNumbers.h>

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace ob = ompl::base;
namespace og = ompl::geometric;
using Clock = std::chrono::steady_clock;

constexpr int N = 4;

struct Box {
    double lo[N], hi[N];
    Box(const std::vector<double> &c, const std::vector<double> &w) {
        for (int d = 0; d < N; ++d) {
            lo[d] = c[d] - 0.5 * w[d] - DBL_EPSILON;
            hi[d] = c[d] + 0.5 * w[d] + DBL_EPSILON;
        }
    }
    bool contains(const double *x) const {
        for (int d = 0; d < N; ++d)
            if (x[d] < lo[d] || x[d] > hi[d]) return false;
        return true;
    }
};

struct World {
    std::string name;
    std::vector<Box> obstacles, antis;
    std::vector<double> start, goal;
    bool valid(const double *x) const {
        for (int d = 0; d < N; ++d)
            if (x[d] < -0.5 || x[d] > 0.5) return false;
        for (const auto &o : obstacles)
            if (o.contains(x)) {
                for (const auto &a : antis)
                    if (a.contains(x)) return true;
                return false;
            }
        return true;
    }
};

// PDT dividing walls, R^4 (shared/spec/problems.md; main/problems/src/dividing_walls.rs).
World dividingWalls() {
    World w;
    w.name = "DW";
    const double walls[3][2] = {{-0.25, 0.05}, {0.0, 0.1}, {0.25, 0.05}};
    for (auto &wl : walls) w.obstacles.emplace_back(std::vector<double>{wl[0], 0, 0, 0}, std::vector<double>{wl[1], 1, 1, 1});
    const double widths[6] = {0.05, 0.03, 0.01, 0.01, 0.03, 0.05};
    for (int j = 1; j <= 6; ++j)
        w.antis.emplace_back(std::vector<double>{0, -0.5 + j / 7.0, 0, 0}, std::vector<double>{1, widths[j - 1], 1, 1});
    w.start = {-0.45, 0, 0, 0};
    w.goal = {0.45, 0, 0, 0};
    return w;
}

// PDT goal enclosure, R^4 (shared/spec/problems.md; main/problems/src/enclosure.rs).
World goalEnclosure() {
    World w;
    w.name = "GE";
    const double gx = 0.2, outside = 0.25, inside = 0.2, gap = 0.2;
    w.obstacles.emplace_back(std::vector<double>{gx, 0, 0, 0}, std::vector<double>(N, outside));
    w.antis.emplace_back(std::vector<double>{gx, 0, 0, 0}, std::vector<double>(N, inside));
    const double shell = 0.5 * (outside - inside);
    w.antis.emplace_back(std::vector<double>{gx + 0.5 * inside + 0.5 * shell, 0, 0, 0},
                         std::vector<double>{shell + 1e-9, gap, gap, gap});
    w.start = {-0.2, 0, 0, 0};
    w.goal = {gx, 0, 0, 0};
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
    auto space = std::make_shared<ob::RealVectorStateSpace>(N);
    space->setBounds(-0.5, 0.5);
    Setup s;
    s.si = std::make_shared<ob::SpaceInformation>(space);
    s.checker = std::make_shared<Checker>(s.si, w);
    s.si->setStateValidityChecker(s.checker);
    s.si->setStateValidityCheckingResolution(5e-6);
    s.si->setup();
    s.pdef = std::make_shared<ob::ProblemDefinition>(s.si);
    ob::ScopedState<> start(space), goal(space);
    for (int d = 0; d < N; ++d) {
        start[d] = w.start[d];
        goal[d] = w.goal[d];
    }
    s.pdef->setStartAndGoalStates(start, goal);  // GoalState, threshold = machine epsilon
    s.pdef->setOptimizationObjective(std::make_shared<ob::PathLengthOptimizationObjective>(s.si));
    return s;
}

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

template <class T> double median(std::vector<T> v) {
    if (v.empty()) return NAN;
    std::sort(v.begin(), v.end());
    size_t n = v.size();
    return n % 2 ? double(v[n / 2]) : 0.5 * (double(v[n / 2 - 1]) + double(v[n / 2]));
}

// One run (one process per run: OMPL 1.5 honours RNG::setSeed only before the first RNG exists).
void runOnce(const World &w, const std::string &planner, unsigned seed, double budget) {
    Setup s = makeSetup(w);
    ob::PlannerPtr p;
    if (planner == "BITstar") {
        auto b = std::make_shared<og::BITstar>(s.si);
        b->setSamplesPerBatch(100);
        b->setRewireFactor(1.001);
        b->setUseKNearest(true);
        b->setStopOnSolnImprovement(true);
        p = b;
    } else {
        auto c = std::make_shared<og::RRTConnect>(s.si);
        c->setRange(0.5);
        p = c;
    }
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
    double first = gotCb ? cbMs : total;
    unsigned long long firstCalls = gotCb ? cbCalls : calls;
    double cost = ok ? s.pdef->getSolutionPath()->length() : NAN;
    // problem,planner,seed,exact,callback,t_first_ms,calls_first,t_total_ms,calls_total,cost,setup_ms
    std::printf("%s,%s,%u,%d,%d,%.4f,%llu,%.4f,%llu,%.6f,%.4f\n", w.name.c_str(), planner.c_str(), seed, ok, gotCb,
                first, firstCalls, total, calls, cost, setupMs);
}

// Validity checks of states interpolated along random fully valid segments of length 0.3,
// step 1e-5 (= 5e-6 * max extent 2), through SpaceInformation::isValid as a motion validator does.
void isolated(const World &w, unsigned long long total) {
    Setup s = makeSetup(w);
    auto space = s.si->getStateSpace();
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> U(-0.5, 0.5);
    std::normal_distribution<double> G(0, 1);
    const double len = 0.3;
    const unsigned steps = (unsigned)std::ceil(len / (5e-6 * space->getMaximumExtent()));
    std::vector<std::pair<std::vector<double>, std::vector<double>>> segs;
    auto segValid = [&](const double *a, const double *b) {
        double x[N];
        for (unsigned j = 0; j <= steps; ++j) {
            double t = double(j) / steps;
            for (int d = 0; d < N; ++d) x[d] = a[d] + t * (b[d] - a[d]);
            if (!w.valid(x)) return false;
        }
        return true;
    };
    const size_t nseg = 200;
    while (segs.size() < nseg) {
        double a[N], b[N], dir[N], nn = 0;
        for (int d = 0; d < N; ++d) a[d] = U(rng), dir[d] = G(rng), nn += dir[d] * dir[d];
        nn = std::sqrt(nn);
        for (int d = 0; d < N; ++d) b[d] = a[d] + len * dir[d] / nn;
        if (segValid(a, b)) segs.emplace_back(std::vector<double>(a, a + N), std::vector<double>(b, b + N));
    }
    ob::State *sa = space->allocState(), *sb = space->allocState(), *si = space->allocState();
    auto load = [&](ob::State *st, const std::vector<double> &v) {
        for (int d = 0; d < N; ++d) st->as<ob::RealVectorStateSpace::StateType>()->values[d] = v[d];
    };
    // Pass 1: interpolate + si->isValid. Pass 2: interpolate only (to subtract).
    for (int pass = 0; pass < 2; ++pass) {
        unsigned long long done = 0, nvalid = 0;
        double sink = 0;
        size_t k = 0;
        s.checker->calls = 0;
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
                    sink += si->as<ob::RealVectorStateSpace::StateType>()->values[1];
            }
        }
        double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
        std::printf("%-3s isolated pass %d (%s): %llu states, %.3f s, %.2f ns/state (valid %llu, checker calls %llu, sink %g)\n",
                    w.name.c_str(), pass, pass == 0 ? "interpolate+isValid" : "interpolate only", done, ns * 1e-9,
                    ns / done, nvalid, s.checker->calls, sink);
    }
    // Pass 2/3: no OMPL in the loop: inline interpolation on raw arrays, World::valid called directly
    // (pass 2) or not at all (pass 3). A floor for the checker itself.
    for (int pass = 2; pass < 4; ++pass) {
        unsigned long long done = 0, nvalid = 0;
        double sink = 0, x[N];
        size_t k = 0;
        auto t0 = Clock::now();
        while (done < total) {
            const auto &sg = segs[k++ % segs.size()];
            const double *a = sg.first.data(), *b = sg.second.data();
            for (unsigned j = 1; j < steps && done < total; ++j, ++done) {
                const double t = double(j) / steps;
                for (int d = 0; d < N; ++d) x[d] = a[d] + t * (b[d] - a[d]);
                if (pass == 2)
                    nvalid += w.valid(x);
                else
                    sink += x[1];
            }
        }
        double ns = std::chrono::duration<double, std::nano>(Clock::now() - t0).count();
        std::printf("%-3s isolated pass %d (%s): %llu states, %.3f s, %.2f ns/state (valid %llu, sink %g)\n",
                    w.name.c_str(), pass, pass == 2 ? "raw interpolate+World::valid" : "raw interpolate only", done,
                    ns * 1e-9, ns / done, nvalid, sink);
    }
    std::printf("%-3s segments: %zu fully valid segments of length %.2f, %u steps each (step %.1e)\n", w.name.c_str(),
                segs.size(), len, steps, len / steps);
    std::fflush(stdout);
    space->freeState(sa);
    space->freeState(sb);
    space->freeState(si);
}

int main(int argc, char **argv) {
    // usage: driver run DW|GE BITstar|RRTConnect SEED   |   driver iso
    std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "run" && argc == 5) ompl::RNG::setSeed((unsigned)std::stoul(argv[4]));  // before any RNG exists
    ompl::msg::setLogLevel(ompl::msg::LOG_ERROR);
    std::vector<World> worlds = {dividingWalls(), goalEnclosure()};
    for (auto &w : worlds)
        if (!w.valid(w.start.data()) || !w.valid(w.goal.data())) {
            std::fprintf(stderr, "%s: start or goal invalid\n", w.name.c_str());
            return 1;
        }
    if (mode == "run" && argc == 5) {
        const World &w = std::string(argv[2]) == "DW" ? worlds[0] : worlds[1];
        runOnce(w, argv[3], (unsigned)std::stoul(argv[4]), 2.0);
        return 0;
    }
    if (mode == "iso") {
        for (auto &w : worlds) isolated(w, 10000000ULL);
        return 0;
    }
    std::fprintf(stderr, "usage: driver run DW|GE BITstar|RRTConnect SEED | driver iso\n");
    return 2;
}
