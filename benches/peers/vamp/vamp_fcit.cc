// VAMP's FCIT* over time on the Panda MotionBenchMaker problems (exported by the shared
// export_problems.py), beside mit-star's `fcit-star` (benches/peers/vamp/README.md).
//
// VAMP's FCIT* (vamp/planning/fcit.hh) has no time limit: it stops at `max_samples` states or
// `max_iterations` batches, or, unless `optimize` is set, at its first solution. Each of its
// iterations searches the graph as it stands and then draws one batch of `batch_size` valid
// samples, so a run whose limit is reached by the batch it just drew never searches that batch.
// It is deterministic for a given random sequence (Halton, reset before every run), and a run
// with more batches repeats a run with fewer and goes on searching (the open set, the sorted
// neighbour lists and the tree carry over), so its cost never rises with the limit.
//
// So, as VAMP's own scripts/convergence_benchmark.py measures it (`optimize = true`, the
// default batch of 1000 and the other defaults, growing limits), each problem is solved again
// and again with a growing number of searched batches B (0, 1, 2, 3, 4, 6, 9, 13, …: a limit of
// `max_samples = 2 + 1000·(B + 1)`, the start and goal included) until a run takes longer than
// the budget. The cost at time T is that of the run with the most batches that ended within T
// (a run the caller could have made); the time to the first solution is that of a run with
// VAMP's default settings (`optimize = false`: it stops after the first search that reaches the
// goal, without drawing the next batch), made when the growing runs solved the problem within
// the budget (it then searches the same batches and stops where they first solved).
//
// Usage: vamp_fcit PROBLEMS.txt [PER_SCENE=20] [BUDGET_S=1] [RUNS_FILE]
// Problems 1..PER_SCENE of each scene that have valid ends (as anytime_arm takes them).
// Output (stdout), one line per problem, in the shape of anytime_arm's `csv=FILE`:
//   scene,index,planner,first_ms,cost_10ms,cost_100ms,cost_1s   (inf: no path by then; runs
//   longer than the budget do not count, so with a budget under 1 s cost_1s is the budget's)
// RUNS_FILE, if given: every run, `scene,index,batches,samples,time_us,cost,solved`, and the
// first-solution run as `batches = -1`.
#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <limits>
#include <string>
#include <vector>

#include <vamp/planning/fcit.hh>
#include <vamp/random/halton.hh>

#include "mbm_problems.hh"

using mbm::Robot;
static constexpr std::size_t rake = vamp::FloatVectorWidth;
using EnvVec = vamp::collision::Environment<vamp::FloatVector<rake>>;
using Params = vamp::planning::FCITStarNeighborParams;
using Settings = vamp::planning::RoadmapSettings<Params>;
using Planner = vamp::planning::FCIT<Robot, rake, Robot::resolution>;

static constexpr double inf = std::numeric_limits<double>::infinity();
static const double moments_us[3] = {10e3, 100e3, 1e6};

struct Run
{
    double us = 0.0;
    double cost = inf;  // the path's length, infinite without one
    std::size_t samples = 0;
};

// VAMP's FCIT* settings as its Python front end makes them (`configure_robot_and_planner_with_
// kwargs("panda", "fcit")`): the neighbour parameters of the robot, everything else default.
static Settings defaults()
{
    return Settings(Params(Robot::dimension, Robot::space_measure()));
}

static Run solve(const mbm::Problem &p, const EnvVec &env, const Settings &settings,
                 std::shared_ptr<vamp::rng::RNG<Robot>> rng)
{
    std::vector<Robot::Configuration> goals(p.goals.begin(), p.goals.end());
    rng->reset();
    const auto started = std::chrono::steady_clock::now();
    auto result = Planner::solve(Robot::Configuration(p.start), goals, env, settings, rng);
    Run run;
    run.us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
    // Without a path the result holds the start alone and the goal's cost-to-come is infinite.
    if (result.path.size() > 1 and std::isfinite(result.cost)) run.cost = result.path.cost();
    run.samples = result.size.empty() ? 0 : result.size.front();
    return run;
}

int main(int argc, char **argv)
{
    if (argc < 2)
    {
        std::cerr << "usage: vamp_fcit PROBLEMS.txt [PER_SCENE] [BUDGET_S] [RUNS_FILE]\n";
        return 2;
    }
    const int per_scene = argc > 2 ? std::stoi(argv[2]) : 20;
    const double budget_us = (argc > 3 ? std::stod(argv[3]) : 1.0) * 1e6;
    std::ofstream runs;
    if (argc > 4)
    {
        runs.open(argv[4]);
        runs << "scene,index,batches,samples,time_us,cost,solved\n";
    }
    std::shared_ptr<vamp::rng::RNG<Robot>> rng = std::make_shared<vamp::rng::Halton<Robot>>();
    const auto batch = defaults().batch_size;
    std::cout << "scene,index,planner,first_ms,cost_10ms,cost_100ms,cost_1s\n";
    for (const auto &p : mbm::read(argv[1]))
    {
        if (not p.valid or p.index > per_scene) continue;
        const EnvVec env(p.env);
        const std::string scene = p.scene.substr(0, p.scene.rfind("_panda"));
        std::vector<Run> ladder;
        // Searched batches 0, 1, 2, 3, 4, then ×1.5 (rounded down): 6, 9, 13, 19, 28, 42, …
        for (std::size_t batches = 0; batches <= 4096; batches = batches < 4 ? batches + 1 : batches * 3 / 2)
        {
            auto settings = defaults();
            settings.optimize = true;
            settings.max_samples = 2 + batch * (batches + 1);
            settings.max_iterations = batches + 1;
            const auto run = solve(p, env, settings, rng);
            ladder.push_back(run);
            if (runs.is_open())
                runs << scene << "," << p.index << "," << batches << "," << run.samples << "," << run.us << ","
                     << run.cost << "," << std::isfinite(run.cost) << "\n";
            if (run.us > budget_us) break;
        }
        double first_ms = inf;
        const bool solved_in_budget = [&] {
            for (const auto &r : ladder)
                if (r.us <= budget_us and std::isfinite(r.cost)) return true;
            return false;
        }();
        if (solved_in_budget)
        {
            const auto run = solve(p, env, defaults(), rng);
            if (std::isfinite(run.cost) and run.us <= budget_us) first_ms = run.us / 1e3;
            if (runs.is_open())
                runs << scene << "," << p.index << ",-1," << run.samples << "," << run.us << "," << run.cost << ","
                     << std::isfinite(run.cost) << "\n";
        }
        std::cout << scene << "," << p.index << ",vamp-fcit-star," << first_ms;
        for (const double m : moments_us)
        {
            double cost = inf;
            for (const auto &r : ladder)
                if (r.us <= m and r.us <= budget_us) cost = r.cost;
            std::cout << "," << cost;
        }
        std::cout << std::endl;
    }
    return 0;
}
