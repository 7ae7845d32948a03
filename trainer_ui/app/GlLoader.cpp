#include "trainer_ui/app/GlLoader.h"

#include <QOpenGLContext>

namespace colonosim::app {

std::unique_ptr<render::GlFunctions> loadQtGlFunctions()
{
    QOpenGLContext* context = QOpenGLContext::currentContext();
    if (context == nullptr) {
        throw render::RenderError("no OpenGL context is current for the view");
    }
    return std::make_unique<render::GlFunctions>(
        [context](const char* name) { return reinterpret_cast<void*>(context->getProcAddress(name)); });
}

}  // namespace colonosim::app
