// The MotionBenchMaker problems as the shared export_problems.py writes them (one `P` line per
// problem, then its start `S`, goals `G` and obstacles), read into VAMP's types; shared by the
// harnesses of this folder (vamp_anytime.cc, vamp_fcit.cc). The robot is the Panda unless the
// build says otherwise: `-DMBM_ROBOT=UR5 -DMBM_ROBOT_HEADER='<vamp/robots/ur5.hh>'` (or
// `Fetch`, `<vamp/robots/fetch.hh>`), for the problems of that robot exported the same way.
#pragma once

#include <array>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <vamp/collision/factory.hh>
#ifndef MBM_ROBOT
#define MBM_ROBOT Panda
#define MBM_ROBOT_HEADER <vamp/robots/panda.hh>
#endif
#include MBM_ROBOT_HEADER

namespace mbm
{
    using Robot = vamp::robots::MBM_ROBOT;
    using EnvIn = vamp::collision::Environment<float>;
    namespace vf = vamp::collision::factory;

    struct Problem
    {
        std::string scene;
        int index = 0;
        bool valid = false;
        Robot::ConfigurationArray start{};
        std::vector<Robot::ConfigurationArray> goals;
        EnvIn env;
    };

    inline std::array<float, 3> three(std::istringstream &s)
    {
        std::array<float, 3> a{};
        s >> a[0] >> a[1] >> a[2];
        return a;
    }

    inline Robot::ConfigurationArray configuration(std::istringstream &s)
    {
        Robot::ConfigurationArray a{};
        for (auto &x : a) s >> x;
        return a;
    }

    inline std::vector<Problem> read(const char *file)
    {
        std::ifstream in(file);
        std::vector<Problem> all;
        std::string line;
        while (std::getline(in, line))
        {
            std::istringstream ss(line);
            std::string tag;
            ss >> tag;
            if (tag == "P")
            {
                all.emplace_back();
                int valid, goals;
                ss >> all.back().scene >> all.back().index >> valid >> goals;
                all.back().valid = valid;
                continue;
            }
            if (all.empty()) continue;
            auto &p = all.back();
            if (tag == "S") p.start = configuration(ss);
            else if (tag == "G") p.goals.push_back(configuration(ss));
            else if (tag == "sphere")
            {
                auto c = three(ss);
                float r;
                ss >> r;
                p.env.spheres.emplace_back(vf::sphere::array(c, r));
            }
            else if (tag == "capsule")
            {
                auto c = three(ss), e = three(ss);
                float r, l;
                ss >> r >> l;
                auto shape = vf::cylinder::center::array(c, e, r, l);
                if (shape.xv == 0. and shape.yv == 0.) p.env.z_aligned_capsules.emplace_back(shape);
                else p.env.capsules.emplace_back(shape);
            }
            else if (tag == "cuboid")
            {
                auto c = three(ss), e = three(ss), h = three(ss);
                auto shape = vf::cuboid::array(c, e, h);
                if (shape.axis_3_z == 1.) p.env.z_aligned_cuboids.emplace_back(shape);
                else p.env.cuboids.emplace_back(shape);
            }
            p.env.sort();
        }
        return all;
    }
}  // namespace mbm
