#pragma once
// stb_image (its Radiance .hdr decoder) and stb_image_write, Debian's headers (libstb-dev), compiled into Specula by
// core/StbImage.cpp under names of its own and with hidden visibility. Include this, never
// <stb/stb_image.h> directly.
//
// Why: Debian's libdraco.so.7 exports a copy of stb_image of its own. With libstb.so linked,
// a stbi_* call bound, at link time and again in the dynamic linker, to whichever library
// defined it first, and that was draco's: every image Specula decoded, and every image the
// fuzzers fuzzed, went through draco's copy, built without the sanitizers. Under these names
// nothing but core/StbImage.cpp defines them, so the linker always takes that object, and
// hidden, they are not exported for another library to bind to.
// (Only the functions Specula calls are renamed; stb's others stay hidden in the same object.)
// stb_image reads Radiance .hdr files only (STBI_ONLY_HDR in core/StbImage.cpp).
#define stbi_failure_reason specula_stbi_failure_reason
#define stbi_image_free specula_stbi_image_free
#define stbi_is_hdr_from_memory specula_stbi_is_hdr_from_memory
#define stbi_loadf_from_callbacks specula_stbi_loadf_from_callbacks
#define stbi_write_png_to_func specula_stbi_write_png_to_func
#define stbi_write_hdr_to_func specula_stbi_write_hdr_to_func
// STBIDEF and STBIWDEF mark stb's own functions and globals; a visibility pragma around the
// includes would hide the C library's declarations that stb includes too.
#define STBIDEF extern __attribute__((visibility("hidden")))
#define STBIWDEF extern "C" __attribute__((visibility("hidden")))
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
