#include "core/ProcessMemory.h"

#include <fstream>

#include <unistd.h>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace specula {

double residentMebibytes()
{
    std::ifstream statm("/proc/self/statm");
    long long pages = 0, resident = 0;
    if (!(statm >> pages >> resident)) return -1.0;
    return double(resident) * double(::sysconf(_SC_PAGESIZE)) / 1048576.0;
}

double heapInUseMebibytes()
{
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 33))
    const struct mallinfo2 info = ::mallinfo2();
    return double(info.uordblks + info.hblkhd) / 1048576.0;
#else
    return -1.0;
#endif
}

} // namespace specula
