// Cost of one VAMP configuration check (its generated Panda fkcc) on 4096 configurations drawn
// uniformly within the joint limits, first valid problem of each scene of panda_mbm.txt: one
// configuration per call (its eight lanes all the same, as VAMP validates one configuration),
// eight per call (a batch ends at its first contact in any lane), and eight valid ones per call.
// Prints: scene, ns per configuration one per call, eight per call, share valid, eight valid per call.
// Written for mit-star's measurements (benches/peers/vamp/README.md); links nothing of VAMP but
// its headers.
#include <chrono>
#include <fstream>
#include <iostream>
#include <map>
#include <random>
#include <sstream>
#include <vamp/collision/factory.hh>
#include <vamp/robots/panda.hh>
using Robot = vamp::robots::Panda;
namespace vf = vamp::collision::factory;
using Env = vamp::collision::Environment<float>;
static std::array<float, 3> r3(std::istringstream &s) { std::array<float, 3> a{}; s >> a[0] >> a[1] >> a[2]; return a; }
int main(int argc, char **argv)
{
    std::ifstream in(argv[1]);
    std::map<std::string, Env> envs;
    std::string line, scene; bool take = false;
    while (std::getline(in, line))
    {
        std::istringstream ss(line); std::string tag; ss >> tag;
        if (tag == "P") { int index, v; ss >> scene >> index >> v; take = v && !envs.count(scene); if (take) envs[scene]; }
        else if (!take) continue;
        else if (tag == "sphere") { auto c = r3(ss); float r; ss >> r; envs[scene].spheres.emplace_back(vf::sphere::array(c, r)); }
        else if (tag == "capsule") { auto c = r3(ss), e = r3(ss); float r, l; ss >> r >> l; auto s = vf::cylinder::center::array(c, e, r, l);
            if (s.xv == 0. and s.yv == 0.) envs[scene].z_aligned_capsules.emplace_back(s); else envs[scene].capsules.emplace_back(s); }
        else if (tag == "cuboid") { auto c = r3(ss), e = r3(ss), h = r3(ss); auto s = vf::cuboid::array(c, e, h);
            if (s.axis_3_z == 1.) envs[scene].z_aligned_cuboids.emplace_back(s); else envs[scene].cuboids.emplace_back(s); }
    }
    const int N = 4096, R = 20;
    std::mt19937 rng(7); std::uniform_real_distribution<float> u(0, 1);
    for (auto &[name, env] : envs)
    {
        env.sort();
        vamp::collision::Environment<vamp::FloatVector<8>> env8(env);
        std::vector<std::array<float, 7>> qs(N);
        for (auto &q : qs) { Robot::Configuration c; std::array<float, 7> a; for (auto &x : a) x = u(rng);
            c = Robot::Configuration(a); Robot::scale_configuration(c); auto full = c.to_array(); for (int j = 0; j < 7; ++j) q[j] = full[j]; }
        int valid = 0; volatile int sink = 0;
        auto t0 = std::chrono::steady_clock::now();
        for (int r = 0; r < R; ++r) { valid = 0; for (auto &q : qs) { Robot::ConfigurationBlock<8> b;
            for (int j = 0; j < 7; ++j) { std::array<float, 8> lane; lane.fill(q[j]); b[j] = vamp::FloatVector<8>(lane); }
            valid += Robot::fkcc<8>(env8, b); } }
        auto t1 = std::chrono::steady_clock::now();
        for (int r = 0; r < R; ++r) for (int i = 0; i < N; i += 8) { Robot::ConfigurationBlock<8> b;
            for (int j = 0; j < 7; ++j) { std::array<float, 8> lane; for (int l = 0; l < 8; ++l) lane[l] = qs[i + l][j]; b[j] = vamp::FloatVector<8>(lane); }
            sink += Robot::fkcc<8>(env8, b); }
        auto t2 = std::chrono::steady_clock::now();
        std::vector<std::array<float, 7>> ok;
        for (auto &q : qs) { Robot::ConfigurationBlock<8> b;
            for (int j = 0; j < 7; ++j) { std::array<float, 8> lane; lane.fill(q[j]); b[j] = vamp::FloatVector<8>(lane); }
            if (Robot::fkcc<8>(env8, b)) ok.push_back(q); }
        while (ok.size() % 8) ok.pop_back();
        auto t3 = std::chrono::steady_clock::now();
        for (int r = 0; r < R; ++r) for (std::size_t i = 0; i < ok.size(); i += 8) { Robot::ConfigurationBlock<8> b;
            for (int j = 0; j < 7; ++j) { std::array<float, 8> lane; for (int l = 0; l < 8; ++l) lane[l] = ok[i + l][j]; b[j] = vamp::FloatVector<8>(lane); }
            sink += Robot::fkcc<8>(env8, b); }
        auto t4 = std::chrono::steady_clock::now();
        double v = std::chrono::duration<double, std::nano>(t4 - t3).count() / (R * ok.size());
        double s = std::chrono::duration<double, std::nano>(t1 - t0).count() / (R * N);
        double b = std::chrono::duration<double, std::nano>(t2 - t1).count() / (R * N);
        std::cout << name << "," << s << "," << b << "," << double(valid) / N << "," << v << "\n";
    }
}
