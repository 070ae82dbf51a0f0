// The frame's constants (shared/FrameData.h), declared once for every file of a shader that
// reads them (the loader includes each file once).
#include "../shared/Bindings.h"
#include "../shared/FrameData.h"

layout(std140, binding = SPECULA_BINDING_FRAME) uniform FrameBlock { FrameData frame; };
