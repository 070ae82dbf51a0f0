#pragma once
// The per-pass time table that `render --stats` and `bench` print.
#include <map>
#include <string>
#include <vector>

#include "render/Renderer.h"

namespace specula::cli {

/// Median times of one pass over several frames.
struct PassSummary {
    std::string name;
    double gpuMs = 0;  ///< timer query
    double wallMs = 0; ///< wall clock with the GPU drained before and after (0 if not measured)
};

/// Each pass's times over several frames, in frame order.
class PassTimes {
public:
    void add(const render::FrameStats& stats);
    /// Medians per pass, in the order the passes ran.
    std::vector<PassSummary> medians() const;

private:
    std::vector<std::string> mOrder;
    std::map<std::string, std::vector<double>> mGpu, mWall;
};

/// Prints "pass  timer ms  wall ms" rows and their totals to stdout, under `title`.
void printPassTable(const std::string& title, const std::vector<PassSummary>& medians);

/// One line of the frame's light clusters (grid, lights in view, max and mean per cluster), or
/// empty when the frame culled no lights.
std::string clusterStatsLine(const render::FrameStats::Clusters& clusters);

} // namespace specula::cli
