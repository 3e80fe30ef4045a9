#include "RackPresets.h"

#include "Racks.h"

#include <QObject>

namespace cuelab {

namespace {
constexpr int kCradleLength = 5;  // balls in the Newton's cradle line
}  // namespace

QString rackName(RackPreset preset)
{
    switch (preset) {
    case RackPreset::Straight: return QObject::tr("Cue ball and one object ball");
    case RackPreset::NineBall: return QObject::tr("9-ball diamond");
    case RackPreset::EightBall: return QObject::tr("8-ball triangle (15 balls)");
    case RackPreset::Cradle: return QObject::tr("Newton's cradle (5 frozen balls)");
    }
    return {};
}

std::vector<Ball> rackBalls(RackPreset preset, const Table& table)
{
    Ball cue;
    cue.id = "cue";
    cue.radius = table.ballRadius;
    cue.mass = table.ballMass;
    cue.state.position = headSpot(table);

    std::vector<Ball> objects;
    switch (preset) {
    case RackPreset::Straight: {
        Ball one = cue;
        one.id = "1";
        one.state.position = footSpot(table);
        objects.push_back(one);
        break;
    }
    case RackPreset::NineBall: objects = rack9Ball(table); break;
    case RackPreset::EightBall: objects = rack8Ball(table); break;
    case RackPreset::Cradle: objects = cradleLine(table, kCradleLength, footSpot(table)); break;
    }
    std::vector<Ball> balls{cue};
    balls.insert(balls.end(), objects.begin(), objects.end());
    return balls;
}

}  // namespace cuelab
