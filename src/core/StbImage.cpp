// The one object that defines stb_image and stb_image_write (why: core/StbImage.h).
// Third-party code: compiled without Specula's warnings (CMakeLists.txt).
#define STB_IMAGE_IMPLEMENTATION
// Radiance .hdr only: PNG and JPEG are libpng's and libjpeg-turbo's (core/ImageDecode.cpp), and
// stb_image's other decoders (its JPEG, PNG, PNM, GIF...) are not even compiled.
#define STBI_ONLY_HDR
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include "core/StbImage.h"
