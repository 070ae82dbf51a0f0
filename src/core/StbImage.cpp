// The one object that defines stb_image and stb_image_write (why: core/StbImage.h).
// Third-party code: compiled without Specula's warnings (CMakeLists.txt).
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include "core/StbImage.h"
