// The cost of one CAPT query (VAMP's point structure) on the clouds side_by_side_clouds.sh saves,
// beside robot/examples/cloud_query.rs (ours) on the same clouds and the same spheres.
// For each .npy cloud (float32, N×3): the CAPT's build (r_min 0.012, r_max 0.08: VAMP's Panda
// radii; points of radius 0.0025), then 4096 spheres in groups of eight within a centimetre of a
// centre drawn uniformly in the cloud's box, radii uniform in [0.012, 0.08] (xorshift64*, seed
// 7, the same draws as ours), each asked one at a time (`collides`) and eight at once
// (`collides_simd`), best of five rounds. Prints: file, points, build µs, ns a sphere one at a
// time, ns a sphere eight at once, spheres touching, groups of eight with one touching.
//   source common.sh; vamp_compile "$W/src/src/impl" capt_query capt_query.cc
//   ./capt_query OUT/clouds/table_pick_0001.npy …
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <vamp/collision/capt.hh>

using vamp::collision::Point;

static auto read_npy(const std::string &path) -> std::vector<Point>
{
    std::ifstream in(path, std::ios::binary);
    std::string all((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto major = static_cast<unsigned char>(all[6]);
    std::size_t header_len, offset;
    if (major == 1) { header_len = static_cast<unsigned char>(all[8]) | (static_cast<unsigned char>(all[9]) << 8); offset = 10; }
    else { std::uint32_t h; std::memcpy(&h, all.data() + 8, 4); header_len = h; offset = 12; }
    const std::string header = all.substr(offset, header_len);
    if (header.find("<f4") == std::string::npos or header.find("False") == std::string::npos)
    {
        std::cerr << path << ": want a C-ordered float32 N×3 array\n";
        std::exit(2);
    }
    const char *data = all.data() + offset + header_len;
    const std::size_t n = (all.size() - offset - header_len) / 12;
    std::vector<Point> points(n);
    for (std::size_t i = 0; i < n; ++i) std::memcpy(points[i].data(), data + 12 * i, 12);
    return points;
}

struct Rng
{
    std::uint64_t x = 7;
    auto next() -> float  // xorshift64*, 24 bits into [0, 1)
    {
        x ^= x >> 12; x ^= x << 25; x ^= x >> 27;
        return static_cast<float>((x * 0x2545F4914F6CDD1DULL) >> 40) * (1.0F / 16777216.0F);
    }
};

int main(int argc, char **argv)
{
    constexpr std::size_t count = 4096;
    std::printf("file,points,build_us,ns_one,ns_eight,touching,groups_touching\n");
    for (int a = 1; a < argc; ++a)
    {
        const auto points = read_npy(argv[a]);
        Point lo = points[0], hi = points[0];
        for (const auto &p : points)
            for (int k = 0; k < 3; ++k) { lo[k] = std::min(lo[k], p[k]); hi[k] = std::max(hi[k], p[k]); }
        Rng rng;
        std::vector<std::array<float, 4>> spheres(count);
        for (std::size_t g = 0; g < count; g += 8)
        {
            std::array<float, 3> c;
            for (int k = 0; k < 3; ++k) c[k] = lo[k] + (hi[k] - lo[k]) * rng.next();
            for (std::size_t j = g; j < g + 8; ++j)
            {
                for (int k = 0; k < 3; ++k) spheres[j][k] = c[k] + 0.01F * (2.0F * rng.next() - 1.0F);
                spheres[j][3] = 0.012F + (0.08F - 0.012F) * rng.next();
            }
        }
        const auto t0 = std::chrono::steady_clock::now();
        vamp::collision::CAPT capt(points, 0.012F, 0.08F, 0.0025F);
        const double build_us = std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - t0).count();
        double best_one = 1e30, best_eight = 1e30;
        std::size_t touching = 0, sink = 0;
        for (int round = 0; round < 5; ++round)
        {
            auto t = std::chrono::steady_clock::now();
            std::size_t hits = 0;
            for (const auto &s : spheres) hits += capt.collides(Point{s[0], s[1], s[2]}, s[3]);
            best_one = std::min(best_one, std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t).count() / count);
            touching = hits;
            t = std::chrono::steady_clock::now();
            for (std::size_t g = 0; g < count; g += 8)
            {
                std::array<float, 8> x, y, z, r;
                for (int j = 0; j < 8; ++j) { x[j] = spheres[g + j][0]; y[j] = spheres[g + j][1]; z[j] = spheres[g + j][2]; r[j] = spheres[g + j][3]; }
                using F = vamp::collision::CAPT::FVectorT;
                sink += capt.collides_simd({F(x), F(y), F(z)}, F(r));
            }
            best_eight = std::min(best_eight, std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - t).count() / count);
        }
        std::printf("%s,%zu,%.1f,%.2f,%.2f,%zu,%zu\n", argv[a], points.size(), build_us, best_one, best_eight, touching, sink / 5);
    }
    return 0;
}
