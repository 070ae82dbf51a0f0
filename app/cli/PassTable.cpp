#include "PassTable.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>

namespace specula::cli {
namespace {

double median(std::vector<double> values)
{
    if (values.empty()) return 0.0;
    std::nth_element(values.begin(), values.begin() + ptrdiff_t(values.size() / 2), values.end());
    return values[values.size() / 2];
}

} // namespace

void PassTimes::add(const render::FrameStats& stats)
{
    for (const render::PassTiming& pass : stats.passes) {
        if (!mGpu.count(pass.name)) mOrder.emplace_back(pass.name);
        mGpu[pass.name].push_back(pass.gpuMs);
        mWall[pass.name].push_back(pass.wallMs);
    }
}

std::vector<PassSummary> PassTimes::medians() const
{
    std::vector<PassSummary> out;
    for (const std::string& name : mOrder) out.push_back({name, median(mGpu.at(name)), median(mWall.at(name))});
    return out;
}

void printPassTable(const std::string& title, const std::vector<PassSummary>& medians)
{
    std::printf("%s\n", title.c_str());
    std::printf("  %-18s %9s %9s\n", "pass", "timer ms", "wall ms");
    double gpu = 0.0, wall = 0.0;
    for (const PassSummary& pass : medians) {
        std::printf("  %-18s %9.2f %9.2f\n", pass.name.c_str(), pass.gpuMs, pass.wallMs);
        gpu += pass.gpuMs;
        wall += pass.wallMs;
    }
    std::printf("  %-18s %9.2f %9.2f\n", "total", gpu, wall);
}

std::string clusterStatsLine(const render::FrameStats::Clusters& c)
{
    if (c.slices == 0) return {};
    return fmt::format("light clusters {}x{}x{}: {} point/spot light{} in view, {} directional; per cluster max {}, mean {:.2f} "
                       "({} entries, {:.1f} MiB buffer)",
                       c.tilesX, c.tilesY, c.slices, c.lightsInView, c.lightsInView == 1 ? "" : "s", c.directional, c.maxPerCluster,
                       c.meanPerCluster, c.entries, double(c.bufferBytes) / (1024.0 * 1024.0));
}

} // namespace specula::cli
