// The inspector in a real window (GLFW + a Vulkan swapchain).
#pragma once

#include "pipeline.h"

#include <string>

namespace lloydscope {

// Runs until the window is closed. Without a display, throws Error with a one-line hint.
int runWindow(const std::string& meshName, const RemeshOptions& options, RemeshResult result,
              bool validation);

}  // namespace lloydscope
