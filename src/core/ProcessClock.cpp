#include "core/ProcessClock.h"

#include <fstream>
#include <sstream>
#include <string>

#include <time.h>
#include <unistd.h>

namespace specula {

double msSinceProcessStart()
{
    // Field 22 of /proc/self/stat is the start time in clock ticks after boot; CLOCK_BOOTTIME
    // counts from the same origin.
    std::ifstream in("/proc/self/stat");
    std::string stat;
    if (!std::getline(in, stat)) return -1.0;
    const size_t paren = stat.rfind(')');
    if (paren == std::string::npos) return -1.0;
    std::istringstream fields(stat.substr(paren + 2));
    std::string field;
    // After "pid (comm) ", state is field 3; starttime is field 22, i.e. the 20th here.
    for (int i = 3; i <= 22 && fields >> field; ++i) {
        if (i == 22) {
            const double ticks = std::stod(field);
            timespec now{};
            clock_gettime(CLOCK_BOOTTIME, &now);
            const double nowMs = double(now.tv_sec) * 1e3 + double(now.tv_nsec) * 1e-6;
            return nowMs - ticks * 1e3 / double(sysconf(_SC_CLK_TCK));
        }
    }
    return -1.0;
}

} // namespace specula
