// Every shader, and the variants the renderer builds, validated offline by glslangValidator
// (Khronos' reference front end), independently of the driver: Mesa and NVIDIA each accept
// things the specification does not.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gl/Program.h"
#include "gl/ShaderSource.h"

namespace fs = std::filesystem;
using specula::gl::loadShaderSource;

namespace {

struct Variant {
    std::string path;
    std::vector<std::string> defines;
};

std::vector<Variant> variants()
{
    std::vector<Variant> out;
    // Every stage file on its own, no defines.
    for (const auto& entry : fs::recursive_directory_iterator(specula::gl::shaderRoot())) {
        const std::string ext = entry.path().extension().string();
        if (ext == ".vert" || ext == ".frag" || ext == ".comp")
            out.push_back({fs::relative(entry.path(), specula::gl::shaderRoot()).generic_string(), {}});
    }
    // The forward pass's feature variants, one at a time and all together.
    const std::vector<std::string> features = {"HAS_BASE_COLOR_TEXTURE", "HAS_METALLIC_ROUGHNESS_TEXTURE", "HAS_NORMAL_TEXTURE",
                                               "HAS_OCCLUSION_TEXTURE",  "HAS_EMISSIVE_TEXTURE",           "DOUBLE_SIDED",
                                               "ALPHA_MASK",             "ALPHA_BLEND",                    "VERTEX_COLOR",
                                               "IBL",                    "ENERGY_COMPENSATION",            "BRDF_G_SCHLICK_GGX",
                                               "SSAO"};
    for (const auto& feature : features) out.push_back({"forward/pbr.frag", {feature}});
    out.push_back({"forward/pbr.frag", features});
    // The material system: every BRDF term, shading model and debug view (docs/materials.md).
    for (const char* define : {"BRDF_D_BECKMANN", "BRDF_D_BLINN_PHONG", "BRDF_G_SMITH_GGX_CORRELATED", "BRDF_G_NEUMANN",
                               "BRDF_G_KELEMEN", "BRDF_G_COOK_TORRANCE", "BRDF_G_IMPLICIT", "BRDF_F_SCHLICK_SG", "BRDF_F_NONE",
                               "BRDF_DIFFUSE_OREN_NAYAR", "BRDF_DIFFUSE_BURLEY", "SHADING_UNLIT", "SHADING_FLAT", "SHADING_GOURAUD",
                               "SHADING_PHONG", "SHADING_BLINN_PHONG", "SHADING_DOOM", "DEBUG_VIEW_BASE_COLOR", "DEBUG_VIEW_NORMAL",
                               "DEBUG_VIEW_ROUGHNESS", "DEBUG_VIEW_METALLIC", "DEBUG_VIEW_OCCLUSION", "DEBUG_VIEW_EMISSIVE",
                               "DEBUG_VIEW_BRDF_D", "DEBUG_VIEW_BRDF_G", "DEBUG_VIEW_BRDF_F"})
        out.push_back({"forward/pbr.frag", {define, "IBL", "HAS_OCCLUSION_TEXTURE"}});
    out.push_back({"forward/pbr.vert", {"SHADING_GOURAUD"}});
    // A Doom frame (render/DoomPass): the forward pass's and the billboards' indexed output.
    out.push_back({"forward/pbr.frag", {"SHADING_DOOM", "DOOM_INDEXED"}});
    out.push_back({"forward/pbr.frag", {"SHADING_DOOM", "DOOM_INDEXED", "HAS_BASE_COLOR_TEXTURE", "ALPHA_BLEND", "VERTEX_COLOR"}});
    out.push_back({"billboard/billboard.vert", {"DOOM_INDEXED"}});
    out.push_back({"billboard/billboard.frag", {"DOOM_INDEXED"}});
    out.push_back({"post/tonemap.frag", {"MSAA_SAMPLES 4"}});
    // Post-processing variants (render/BloomPass, SsaoPass, Renderer's tone mapper for FXAA).
    out.push_back({"post/tonemap.frag", {"MSAA_SAMPLES 4", "AUTO_EXPOSURE", "ENCODE_SRGB"}});
    out.push_back({"post/bloom_downsample.comp", {"FIRST_LEVEL"}});
    out.push_back({"post/bloom_downsample.comp", {"FIRST_LEVEL", "KARIS_AVERAGE"}});
    out.push_back({"forward/prepass.frag", {"ALPHA_MASK", "HAS_BASE_COLOR_TEXTURE", "VERTEX_COLOR"}});
    // The DFG bake (render/ImageBasedLighting): each D, G and F define it is made with, alone
    // (the groups are independent dispatches) and one from every group together.
    for (const char* define : {"BRDF_D_BECKMANN", "BRDF_D_BLINN_PHONG", "BRDF_G_SCHLICK_GGX", "BRDF_G_SMITH_GGX_CORRELATED",
                               "BRDF_G_NEUMANN", "BRDF_G_KELEMEN", "BRDF_G_COOK_TORRANCE", "BRDF_G_IMPLICIT", "BRDF_F_SCHLICK_SG"})
        out.push_back({"ibl/dfg.comp", {define}});
    out.push_back({"ibl/dfg.comp", {"BRDF_D_BLINN_PHONG", "BRDF_G_KELEMEN", "BRDF_F_SCHLICK_SG"}});
    return out;
}

} // namespace

TEST(Glslang, EveryShaderVariantValidates)
{
    ASSERT_EQ(std::system("command -v glslangValidator >/dev/null"), 0) << "glslangValidator missing (Debian: glslang-tools)";
    const fs::path dir = fs::temp_directory_path() / "specula-glslang";
    fs::create_directories(dir);
    int index = 0;
    for (const Variant& v : variants()) {
        const auto source = loadShaderSource(specula::gl::shaderRoot(), v.path, v.defines);
        // glslangValidator infers the stage from the extension.
        const fs::path file = dir / (std::to_string(index++) + fs::path(v.path).extension().string());
        std::ofstream(file) << source.text;
        const fs::path log = dir / "log.txt";
        const int status = std::system(("glslangValidator " + file.string() + " >" + log.string() + " 2>&1").c_str());
        std::ifstream in(log);
        const std::string output((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::string defines;
        for (const auto& d : v.defines) defines += d + " ";
        EXPECT_EQ(status, 0) << v.path << " [" << defines << "]\n" << specula::gl::mapShaderLog(output, source.files);
    }
    fs::remove_all(dir);
}
