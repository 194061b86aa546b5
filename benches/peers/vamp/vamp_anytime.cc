// VAMP's AORRTC over time on the Panda MotionBenchMaker problems (exported by the shared
// export_problems.py), for mit-star's anytime comparison (benches/peers/vamp/README.md).
//
// VAMP's AORRTC has no time limit, only an iteration limit, and is deterministic for a given
// random sequence (Halton, reset before every run). So each problem is solved again and again
// with a growing iteration limit K (1, 2, 5, 10, 20, 50, …) until a run takes longer than the
// budget. anytime_table.py takes as the cost at time T that of the run with the largest K that
// ended within T, and as the time to the first solution that of the smallest K that solved.
// (Runs with a larger K do not exactly repeat those with a smaller one: their costs are not
// monotone in K.) Default AORRTC settings (RRT-Connect range 1, simplification of every
// solution inside the planner), as VAMP's scripts use.
//
// Usage: vamp_anytime PROBLEMS.txt [PER_SCENE=20] [BUDGET_S=1] [PATHS_FILE]
// Output (stdout), one line per run: scene,index,limit,time_us,cost,solved
// With the environment variable VAMP_FIRST_PATHS set, it prints instead, per problem, the length
// of RRT-Connect's first path (range 1, the Halton sequence reset), the length after VAMP's
// default simplification (the one its AORRTC applies to every solution) and the simplification's
// time: scene,index,raw_cost,simplified_cost,simplify_us,solved
// With PATHS_FILE: the final path of the last run of each problem, as lines
// `scene index` then one configuration per line, then an empty line.
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <vamp/collision/factory.hh>
#include <vamp/planning/aorrtc.hh>
#include <vamp/random/halton.hh>

#include "mbm_problems.hh"

using mbm::Robot;
static constexpr std::size_t rake = vamp::FloatVectorWidth;
using EnvVec = vamp::collision::Environment<vamp::FloatVector<rake>>;
using Planner = vamp::planning::AORRTC<Robot, rake, Robot::resolution>;
using Connect = vamp::planning::RRTC<Robot, rake, Robot::resolution>;

int main(int argc, char **argv)
{
    if (argc < 2)
    {
        std::cerr << "usage: vamp_anytime PROBLEMS.txt [PER_SCENE] [BUDGET_S] [PATHS_FILE]\n";
        return 2;
    }
    const int per_scene = argc > 2 ? std::stoi(argv[2]) : 20;
    const double budget_us = (argc > 3 ? std::stod(argv[3]) : 1.0) * 1e6;
    std::ofstream paths;
    if (argc > 4) paths.open(argv[4]);
    std::map<std::string, int> taken;
    auto rng = std::make_shared<vamp::rng::Halton<Robot>>();
    const bool first_paths = std::getenv("VAMP_FIRST_PATHS") != nullptr;
    std::cout << (first_paths ? "scene,index,raw_cost,simplified_cost,simplify_us,solved\n"
                              : "scene,index,limit,time_us,cost,solved\n");
    for (const auto &p : mbm::read(argv[1]))
    {
        if (not p.valid or taken[p.scene] >= per_scene) continue;
        ++taken[p.scene];
        EnvVec env(p.env);
        std::vector<Robot::Configuration> goals(p.goals.begin(), p.goals.end());
        if (first_paths)
        {
            vamp::planning::RRTCSettings settings;
            settings.range = 1.0;
            rng->reset();
            auto found = Connect::solve(Robot::Configuration(p.start), goals, env, settings, rng);
            const bool solved = not found.path.empty();
            double raw = -1.0, simplified = -1.0, us = 0.0;
            if (solved)
            {
                raw = found.path.cost();
                const auto started = std::chrono::steady_clock::now();
                auto result = vamp::planning::simplify<Robot, rake, Robot::resolution>(
                    found.path, env, vamp::planning::SimplifySettings{}, rng);
                us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started)
                         .count();
                simplified = result.path.cost();
            }
            std::cout << p.scene << "," << p.index << "," << raw << "," << simplified << "," << us << ","
                      << solved << "\n";
            continue;
        }
        vamp::planning::PlanningResult<Robot> last;
        // 1, 2, 5, 10, 20, 50, …
        for (std::size_t limit = 1, step = 0;; limit = (step % 3 == 1) ? limit * 5 / 2 : limit * 2, ++step)
        {
            vamp::planning::AORRTCSettings settings;
            settings.rrtc.range = 1.0;
            settings.max_iterations = limit;
            rng->reset();
            const auto started = std::chrono::steady_clock::now();
            auto result = Planner::solve(Robot::Configuration(p.start), goals, env, settings, rng);
            const double us =
                std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - started).count();
            const bool solved = not result.path.empty();
            std::cout << p.scene << "," << p.index << "," << limit << "," << us << ","
                      << (solved ? result.path.cost() : -1.0) << "," << solved << "\n";
            if (solved) last = result;
            if (us > budget_us or limit > 50000000) break;
        }
        if (paths.is_open() and not last.path.empty())
        {
            paths << p.scene << " " << p.index << "\n";
            for (const auto &c : last.path)
            {
                const auto a = c.to_array();
                for (auto i = 0U; i < Robot::dimension; ++i) paths << (i ? " " : "") << a[i];
                paths << "\n";
            }
            paths << "\n";
        }
    }
    return 0;
}
