#include "OpenGLProbe.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QSurfaceFormat>

namespace cuelab {

bool probeOpenGL(QString* message)
{
    QSurfaceFormat format = QSurfaceFormat::defaultFormat();
    format.setVersion(kGlMajor, kGlMinor);
    format.setProfile(QSurfaceFormat::CoreProfile);

    QOpenGLContext context;
    context.setFormat(format);
    if (!context.create()) {
        *message = QStringLiteral("CueLab could not create an OpenGL context. The table view needs "
                                  "OpenGL %1.%2 (core profile); check the graphics driver "
                                  "(for example Mesa's libgl1-mesa-dri).")
                       .arg(kGlMajor)
                       .arg(kGlMinor);
        return false;
    }
    const QSurfaceFormat got = context.format();
    if (std::make_pair(got.majorVersion(), got.minorVersion()) < std::make_pair(kGlMajor, kGlMinor)) {
        *message = QStringLiteral("CueLab needs OpenGL %1.%2 but the driver offers only %3.%4.")
                       .arg(kGlMajor)
                       .arg(kGlMinor)
                       .arg(got.majorVersion())
                       .arg(got.minorVersion());
        return false;
    }
    QOffscreenSurface surface;
    surface.setFormat(got);
    surface.create();
    if (!surface.isValid() || !context.makeCurrent(&surface)) {
        *message = QStringLiteral("CueLab created an OpenGL context but could not make it current.");
        return false;
    }
    context.doneCurrent();
    return true;
}

}  // namespace cuelab
