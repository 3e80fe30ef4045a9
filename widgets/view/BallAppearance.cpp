#include "BallAppearance.h"

#include "TableMesh.h"

#include <QString>

#include <algorithm>
#include <cmath>

#include <array>

namespace cuelab {

namespace {

// Pool ball colours 1-8 (9-15 repeat 1-7 as stripes): yellow, blue, red, purple, orange, green,
// maroon, black.
const std::array<QVector3D, 8> kPoolColours{{
    {0.96f, 0.74f, 0.04f},
    {0.06f, 0.20f, 0.72f},
    {0.82f, 0.06f, 0.06f},
    {0.36f, 0.10f, 0.55f},
    {0.97f, 0.42f, 0.04f},
    {0.03f, 0.45f, 0.22f},
    {0.48f, 0.08f, 0.07f},
    {0.04f, 0.04f, 0.04f},
}};

const QVector3D kWhite(0.95f, 0.94f, 0.89f);

struct NamedColour {
    const char* name;
    QVector3D colour;
};

// Snooker and carom colours; also accepted on any table (an id such as "red3" counts as "red").
const std::array<NamedColour, 9> kNamedColours{{
    {"white", kWhite},
    {"cue", kWhite},
    {"red", {0.78f, 0.05f, 0.05f}},
    {"yellow", {0.96f, 0.78f, 0.06f}},
    {"green", {0.04f, 0.42f, 0.16f}},
    {"brown", {0.40f, 0.22f, 0.08f}},
    {"blue", {0.08f, 0.22f, 0.75f}},
    {"pink", {0.96f, 0.50f, 0.62f}},
    {"black", {0.04f, 0.04f, 0.04f}},
}};

}  // namespace

BallLook ballLook(TableKind kind, const std::string& id)
{
    BallLook look;
    const QString text = QString::fromStdString(id).trimmed().toLower();
    bool isNumber = false;
    const int n = text.toInt(&isNumber);
    const bool pool = kind == TableKind::Pool9ft || kind == TableKind::Pool8ft || kind == TableKind::Pool7ft;
    if (isNumber && n >= 1 && n <= 15) {
        look.colour = kPoolColours[static_cast<std::size_t>((n - 1) % 8)];
        look.number = pool ? n : 0;
        look.striped = n >= 9;
        return look;
    }
    for (const NamedColour& named : kNamedColours) {
        if (text.startsWith(QLatin1String(named.name))) {
            look.colour = named.colour;
            // Only the pool cue ball wears dots; a carom "white" stays plain.
            look.dotted = text == QLatin1String("cue") && kind != TableKind::Carom;
            return look;
        }
    }
    return look;
}

QColor displayColour(const QVector3D& linear)
{
    auto g = [](float v) { return static_cast<float>(std::pow(std::clamp(static_cast<double>(v), 0.0, 1.0), 1.0 / 2.2)); };
    return QColor::fromRgbF(g(linear.x()), g(linear.y()), g(linear.z()));
}

QColor paperColour(QColor colour)
{
    if (colour.lightnessF() > 0.6) colour = colour.darker(colour.saturationF() < 0.2 ? 260 : 150);
    return colour;
}

QVector3D pathColour(const BallLook& look, TableKind kind)
{
    const QVector3D grey(0.85f, 0.85f, 0.85f);
    const QVector3D c = look.colour;
    const float brightness = 0.3f * c.x() + 0.59f * c.y() + 0.11f * c.z();
    // Blend towards light grey so black, maroon or blue paths stay visible on green cloth.
    float lift = brightness >= 0.25f ? 0.0f : (0.25f - brightness) / 0.25f * 0.6f;
    // And away from the cloth's own colour: at least 0.35 apart in display (sRGB) units.
    const QColor cloth = displayColour(clothColour(kind));
    const auto distance = [&](const QVector3D& v) {
        const QColor d = displayColour(v);
        const double r = d.redF() - cloth.redF(), g = d.greenF() - cloth.greenF(), b = d.blueF() - cloth.blueF();
        return std::sqrt(r * r + g * g + b * b);
    };
    while (lift < 0.9f && distance((1.0f - lift) * c + lift * grey) < 0.35) lift += 0.05f;
    return (1.0f - lift) * c + lift * grey;
}

}  // namespace cuelab
