#include "DisplayNames.h"

#include <QCoreApplication>
#include <QStringList>

#include <utility>

namespace cuelab {

namespace {

// Listed for lupdate: every name the core gives (core/physics/Names.cpp).
[[maybe_unused]] const char* const kNames[] = {
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "stationary"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "spinning"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "sliding"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "rolling"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "pocketed"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "airborne"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "off-table"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "cue-strike"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "ball-ball"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "ball-cushion"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "ball-pocket"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "ball-table"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "ball-off-table"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "slide-to-roll"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "slide-to-spin"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "slide-to-stop"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "roll-to-spin"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "roll-to-stop"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "spin-to-stop"),
    // The models' names that are words (the others are their authors' names).
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "frictionless"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "frictional"),
    QT_TRANSLATE_NOOP("cuelab::DisplayNames", "mirror"),
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
QString displayCoreName(std::string_view name) { return translated(name); }
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


QString displayKeyName(const std::string& key)
{
    static const std::pair<const char*, const char*> kNames[] = {
        {"shot.heading", QT_TRANSLATE_NOOP("cuelab", "Heading (°)")},
        {"shot.speed", QT_TRANSLATE_NOOP("cuelab", "Cue speed (m/s)")},
        {"shot.elevation", QT_TRANSLATE_NOOP("cuelab", "Cue elevation (°)")},
        {"shot.side", QT_TRANSLATE_NOOP("cuelab", "Tip offset, side (R)")},
        {"shot.height", QT_TRANSLATE_NOOP("cuelab", "Tip offset, height (R)")},
        {"shot.cue_mass", QT_TRANSLATE_NOOP("cuelab", "Cue mass (kg)")},
        {"shot.end_mass", QT_TRANSLATE_NOOP("cuelab", "Cue end mass (kg)")},
        {"physics.mu_slide", QT_TRANSLATE_NOOP("cuelab", "Sliding friction μs")},
        {"physics.mu_roll", QT_TRANSLATE_NOOP("cuelab", "Rolling resistance μr")},
        {"physics.mu_spin", QT_TRANSLATE_NOOP("cuelab", "Spin friction μsp")},
        {"physics.gravity", QT_TRANSLATE_NOOP("cuelab", "Gravity (m/s²)")},
        {"physics.ball_ball.restitution", QT_TRANSLATE_NOOP("cuelab", "Ball-ball restitution e")},
        {"physics.ball_ball.friction", QT_TRANSLATE_NOOP("cuelab", "Ball-ball friction μb")},
        {"physics.ball_cushion.restitution", QT_TRANSLATE_NOOP("cuelab", "Cushion restitution e")},
        {"physics.ball_cushion.friction", QT_TRANSLATE_NOOP("cuelab", "Cushion friction μ")},
        {"table.length", QT_TRANSLATE_NOOP("cuelab", "Table length (m)")},
        {"table.width", QT_TRANSLATE_NOOP("cuelab", "Table width (m)")},
        {"table.cushion_height", QT_TRANSLATE_NOOP("cuelab", "Cushion height (m)")},
        {"simulation.frame_dt", QT_TRANSLATE_NOOP("cuelab", "Frame step (s)")},
        {"simulation.max_time", QT_TRANSLATE_NOOP("cuelab", "Time limit (s)")},
    };
    for (const auto& [k, name] : kNames)
        if (key == k) return tr(name);
    // balls.ID.FIELD
    const QString s = QString::fromStdString(key);
    if (s.startsWith(QLatin1String("balls."))) {
        const qsizetype dot = s.lastIndexOf(QLatin1Char('.'));
        const QString id = s.mid(6, dot - 6);
        const QString field = s.mid(dot + 1);
        const std::pair<const char*, const char*> fields[] = {
            {"x", QT_TRANSLATE_NOOP("cuelab", "x (m)")},          {"y", QT_TRANSLATE_NOOP("cuelab", "y (m)")},
            {"vx", QT_TRANSLATE_NOOP("cuelab", "vx (m/s)")},      {"vy", QT_TRANSLATE_NOOP("cuelab", "vy (m/s)")},
            {"wx", QT_TRANSLATE_NOOP("cuelab", "ωx (rad/s)")},    {"wy", QT_TRANSLATE_NOOP("cuelab", "ωy (rad/s)")},
            {"wz", QT_TRANSLATE_NOOP("cuelab", "ωz (rad/s)")},    {"radius", QT_TRANSLATE_NOOP("cuelab", "radius (m)")},
            {"mass", QT_TRANSLATE_NOOP("cuelab", "mass (kg)")},
        };
        for (const auto& [f, name] : fields)
            if (field == QLatin1String(f)) return tr("Ball %1, %2").arg(id, tr(name));
    }
    // The model's own parameters (physics.ball_cushion.steps, ...): the key's last part.
    if (s.startsWith(QLatin1String("physics.ball_cushion.")))
        return tr("Cushion model's %1").arg(s.mid(21).replace(QLatin1Char('_'), QLatin1Char(' ')));
    return s;
}

}  // namespace cuelab
