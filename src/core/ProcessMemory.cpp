#include "core/ProcessMemory.h"

#include <fstream>

#include <unistd.h>

namespace specula {

double residentMebibytes()
{
    std::ifstream statm("/proc/self/statm");
    long long pages = 0, resident = 0;
    if (!(statm >> pages >> resident)) return -1.0;
    return double(resident) * double(::sysconf(_SC_PAGESIZE)) / 1048576.0;
}

} // namespace specula
