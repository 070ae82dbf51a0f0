// Every shader, and the variants the renderer builds, validated offline by glslangValidator
// (Khronos' reference front end), independently of the driver: Mesa and NVIDIA each accept
// things the specification does not.
#include <unistd.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "gl/Program.h"
#include "gl/ShaderSource.h"
#include "shading/EnvironmentMap.h"
#include "shading/VariantKey.h"

namespace fs = std::filesystem;
using specula::gl::loadShaderSource;
using specula::render::forwardVariantTable;
using specula::render::VariantDefine;

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
    // The forward pass's variants from its variant key's table (shading/VariantKey): every row
    // alone, every row with image-based light and an occlusion texture, and every flag (the
    // rows that combine freely) together.
    std::vector<std::string> flags;
    for (const VariantDefine& row : forwardVariantTable()) {
        out.push_back({"forward/pbr.frag", {row.define}});
        out.push_back({"forward/pbr.frag", {row.define, "IBL", "HAS_OCCLUSION_TEXTURE"}});
        if (row.kind == VariantDefine::Kind::MaterialFeature || row.kind == VariantDefine::Kind::FrameFeature)
            flags.push_back(row.define);
    }
    out.push_back({"forward/pbr.frag", flags});
    // A few lights everywhere: their count a constant (ForwardVariant::defines, outside the table).
    out.push_back({"forward/pbr.frag", {"LIGHTS_ALL", "LIGHT_COUNT 3u", "NO_DIRECTIONAL_LIGHTS"}});
    out.push_back({"forward/pbr.vert", {"SHADING_GOURAUD", "LIGHTS_ALL", "LIGHT_COUNT 2u", "NO_SPOT_LIGHTS"}});
    out.push_back({"forward/pbr.frag", {"SHADING_PHONG", "LIGHTS_ALL", "LIGHT_COUNT 0u", "NO_DIRECTIONAL_LIGHTS", "NO_POINT_LIGHTS", "NO_SPOT_LIGHTS"}});
    out.push_back({"forward/pbr.vert", {"SHADING_GOURAUD"}});
    // A Doom frame (render/DoomPass): the forward pass's and the billboards' indexed output.
    out.push_back({"forward/pbr.frag", {"SHADING_DOOM", "DOOM_INDEXED"}});
    out.push_back({"forward/pbr.frag", {"SHADING_DOOM", "DOOM_INDEXED", "HAS_BASE_COLOR_TEXTURE", "ALPHA_BLEND", "VERTEX_COLOR"}});
    out.push_back({"billboard/billboard.vert", {"DOOM_INDEXED"}});
    out.push_back({"billboard/billboard.frag", {"DOOM_INDEXED"}});
    out.push_back({"post/tonemap.frag", {"MSAA_SAMPLES 4", "TONEMAP_OPERATOR 5u"}});
    out.push_back({"ibl/skybox.frag", {"SKYBOX_BLURRED"}});
    // Post-processing variants (render/BloomPass, SsaoPass, Renderer's tone mapper for FXAA).
    out.push_back({"post/tonemap.frag", {"MSAA_SAMPLES 4", "AUTO_EXPOSURE", "ENCODE_SRGB"}});
    out.push_back({"post/bloom_downsample.comp", {"FIRST_LEVEL"}});
    out.push_back({"post/bloom_downsample.comp", {"FIRST_LEVEL", "KARIS_AVERAGE"}});
    out.push_back({"forward/prepass.frag", {"ALPHA_MASK", "HAS_BASE_COLOR_TEXTURE", "VERTEX_COLOR"}});
    // Transparency (render/passes/ForwardPass): the opaque frame's copy and OIT's composite.
    out.push_back({"transparency/opaque_copy.frag", {"MULTISAMPLE", "ENVIRONMENT_BEHIND"}});
    out.push_back({"transparency/opaque_copy.frag", {"ENVIRONMENT_BEHIND"}});
    out.push_back({"transparency/oit_composite.frag", {"MULTISAMPLE"}});
    out.push_back({"forward/pbr.frag", {"TRANSMISSION", "ALPHA_BLEND", "BLEND_TRANSPARENT", "OIT", "IBL", "ENERGY_COMPENSATION"}});
    // KHR_materials_anisotropy with the importance-sampled lobe, a normal map and back faces, and
    // its D and G debug views.
    out.push_back({"forward/pbr.frag", {"ANISOTROPY", "IBL", "IBL_IMPORTANCE", "ENERGY_COMPENSATION", "HAS_NORMAL_TEXTURE", "DOUBLE_SIDED"}});
    out.push_back({"forward/pbr.frag", {"ANISOTROPY", "DEBUG_VIEW_BRDF_D", "DOUBLE_SIDED"}});
    out.push_back({"forward/pbr.frag", {"ANISOTROPY", "DEBUG_VIEW_BRDF_G"}});
    // The DFG bake (render/ImageBasedLighting): each D, G and F define it is made with, alone
    // (the groups are independent dispatches) and one from every group together.
    for (const char* define : {"BRDF_D_BECKMANN", "BRDF_D_BLINN_PHONG", "BRDF_G_SCHLICK_GGX", "BRDF_G_SMITH_GGX_CORRELATED",
                               "BRDF_G_NEUMANN", "BRDF_G_KELEMEN", "BRDF_G_COOK_TORRANCE", "BRDF_G_IMPLICIT", "BRDF_F_SCHLICK_SG"})
        out.push_back({"ibl/dfg.comp", {define}});
    out.push_back({"ibl/dfg.comp", {"BRDF_D_BLINN_PHONG", "BRDF_G_KELEMEN", "BRDF_F_SCHLICK_SG"}});
    // The forward programs take the environment's bright sources as constants: none, or some
    // (render/passes/ForwardPass, ibl/ibl.glsl), with the other defines as above.
    const std::vector<specula::render::IrradianceSource> sources{{{0.0f, 1.0f, 0.0f}, {1.5f, 1.25f, 1e-5f}},
                                                                 {{0.6f, 0.0f, -0.8f}, {3e4f, 2e4f, 1e4f}}};
    for (Variant& v : out) {
        if (v.path != "forward/pbr.frag") continue;
        const auto defines = specula::render::irradianceSourceDefines((&v - out.data()) % 2 ? std::span(sources) : std::span(sources).first(0));
        v.defines.insert(v.defines.end(), defines.begin(), defines.end());
    }
    return out;
}

} // namespace

TEST(Glslang, EveryShaderVariantValidates)
{
    ASSERT_EQ(std::system("command -v glslangValidator >/dev/null"), 0) << "glslangValidator missing (Debian: glslang-tools)";
    const fs::path dir = fs::temp_directory_path() / ("specula-glslang-" + std::to_string(::getpid()));
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
