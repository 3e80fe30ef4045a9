#include "DisplayNames.h"

#include <QCoreApplication>

namespace cuelab {

namespace {

// Listed for lupdate: every name the core gives (core/physics/Names.cpp).
[[maybe_unused]] const char* const kNames[] = {
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "stationary"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "spinning"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "sliding"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "rolling"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "pocketed"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "cue-strike"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "ball-ball"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "ball-cushion"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "ball-pocket"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "slide-to-roll"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "slide-to-spin"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "slide-to-stop"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "roll-to-spin"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "roll-to-stop"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "spin-to-stop"),
};

QString translated(std::string_view name)
{
    const std::string text(name);  // translate() wants a NUL-terminated key
    return QCoreApplication::translate("cuelab::DisplayNames", text.c_str());
}

}  // namespace

QString displayName(MotionState state) { return translated(toString(state)); }
QString displayName(EventKind kind) { return translated(toString(kind)); }

QString eventNumber(int index) { return QStringLiteral("#%1").arg(index + 1); }

}  // namespace cuelab
