#include "specula/Version.h"

namespace specula {

const char* versionString()
{
    return SPECULA_VERSION_STRING;
}

} // namespace specula
