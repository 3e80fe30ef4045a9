#include "DisplayNames.h"

#include <QCoreApplication>
#include <QStringList>

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

// The context lupdate gives tr() calls in functions of namespace cuelab (resources/translations).
QString tr(const char* text) { return QCoreApplication::translate("cuelab", text); }

}  // namespace

QString displayName(MotionState state) { return translated(toString(state)); }
QString displayName(EventKind kind) { return translated(toString(kind)); }

QString eventNumber(int index) { return QStringLiteral("#%1").arg(index + 1); }

QString displayElementName(const std::string& id)
{
    const QString s = QString::fromStdString(id);
    const QStringList part = s.split(QLatin1Char('-'));
    const auto pocket = [](const QString& code) -> QString {
        if (code == QLatin1String("bl")) return tr("bottom-left pocket");
        if (code == QLatin1String("br")) return tr("bottom-right pocket");
        if (code == QLatin1String("tl")) return tr("top-left pocket");
        if (code == QLatin1String("tr")) return tr("top-right pocket");
        if (code == QLatin1String("b")) return tr("bottom side pocket");
        if (code == QLatin1String("t")) return tr("top side pocket");
        return {};
    };
    const auto rail = [](const QString& code) -> QString {
        if (code == QLatin1String("b") || code == QLatin1String("bottom")) return tr("bottom rail");
        if (code == QLatin1String("t") || code == QLatin1String("top")) return tr("top rail");
        if (code == QLatin1String("l") || code == QLatin1String("left")) return tr("left rail");
        if (code == QLatin1String("r") || code == QLatin1String("right")) return tr("right rail");
        return {};
    };
    const auto half = [](const QString& code) -> QString {
        if (code == QLatin1String("left")) return tr("left half");
        if (code == QLatin1String("right")) return tr("right half");
        return {};
    };
    if (part.size() == 2 && part[0] == QLatin1String("pocket") && !pocket(part[1]).isEmpty()) return pocket(part[1]);
    if (part.size() == 2 && part[0] == QLatin1String("rail") && !rail(part[1]).isEmpty()) return rail(part[1]);
    if (part.size() == 3 && part[0] == QLatin1String("rail") && !rail(part[1]).isEmpty() && !half(part[2]).isEmpty())
        return tr("%1 (%2)").arg(rail(part[1]), half(part[2]));
    if (part.size() == 3 && (part[0] == QLatin1String("jaw") || part[0] == QLatin1String("facing")) && !pocket(part[1]).isEmpty()) {
        const QString where = !half(part[2]).isEmpty() ? half(part[2]) : rail(part[2]);
        if (!where.isEmpty())
            return (part[0] == QLatin1String("jaw") ? tr("jaw of the %1, %2") : tr("facing of the %1, %2")).arg(pocket(part[1]), where);
    }
    return s;
}


}  // namespace cuelab
