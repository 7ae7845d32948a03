#pragma once
/// \file
/// The renderer's GL entry points from the current Qt OpenGL context
/// (QOpenGLContext::getProcAddress), so the views draw through the same
/// driver Qt composes with.

#include "simcore/render/GlFunctions.h"

#include <memory>

namespace colonosim::app {

/// Needs a current QOpenGLContext; throws render::RenderError otherwise.
[[nodiscard]] std::unique_ptr<render::GlFunctions> loadQtGlFunctions();

}  // namespace colonosim::app
