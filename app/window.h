// The inspector in a real window (GLFW + a Vulkan swapchain).
#pragma once

#include "inspector.h"
#include "pipeline.h"

#include <optional>
#include <string>

namespace lloydscope {

// Runs until the window is closed. Without a display, throws Error with a one-line hint.
// Throws Error with a one-line hint (screenshot mode, remesh, xvfb-run) when there is none.
void requireDisplay();

// With the input mesh, the inspector can step, run and remesh again. `uiScale`: pixels per unit
// of the layout (2 draws everything twice as large, for a screen twice as dense); 0: the
// screen's own content scale (GLFW's: on X11 its Xft.dpi over 96), 1 at least.
int runWindow(const std::string& meshName, const RemeshOptions& options, RemeshResult result,
              bool validation, std::optional<Mesh> input, const OpeningView& view = {}, double uiScale = 0);

}  // namespace lloydscope
