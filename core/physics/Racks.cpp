#include "Racks.h"

#include <array>
#include <cmath>
#include <string>

namespace cuelab {

namespace {

Ball makeBall(const Table& table, std::string id, const Vec2& position)
{
    Ball b;
    b.id = std::move(id);
    b.radius = table.ballRadius;
    b.mass = table.ballMass;
    b.state.position = position;
    return b;
}

// Centre of the ball in row `row` (0 = apex), place `k` (0..row), rows stacked towards +x: the
// centres of touching rows are sqrt(3) R apart along x and 2R apart along y.
Vec2 trianglePosition(const Vec2& apex, double radius, int row, int k)
{
    const double dx = std::sqrt(3.0) * radius;
    return apex + Vec2(dx * row, radius * (2.0 * k - row));
}

}  // namespace

Vec2 footSpot(const Table& table) { return Vec2(0.75 * table.length, 0.5 * table.width); }
Vec2 headSpot(const Table& table) { return Vec2(0.25 * table.length, 0.5 * table.width); }

std::vector<Ball> rack8Ball(const Table& table)
{
    // Row by row from the apex: 1; 9 2; 10 8 3; 11 7 14 4; 5 13 15 6 12 (8 in the middle of row 3,
    // a solid (5) and a stripe (12) in the back corners).
    static constexpr std::array<int, 15> order{1, 9, 2, 10, 8, 3, 11, 7, 14, 4, 5, 13, 15, 6, 12};
    std::vector<Ball> balls;
    const Vec2 apex = footSpot(table);
    int n = 0;
    for (int row = 0; row < 5; ++row)
        for (int k = 0; k <= row; ++k)
            balls.push_back(makeBall(table, std::to_string(order[static_cast<std::size_t>(n++)]),
                                     trianglePosition(apex, table.ballRadius, row, k)));
    return balls;
}

std::vector<Ball> rack9Ball(const Table& table)
{
    // Rows 1, 2, 3, 2, 1: the 1 at the apex, the 9 in the middle.
    static constexpr std::array<int, 9> order{1, 2, 3, 4, 9, 5, 6, 7, 8};
    static constexpr std::array<int, 5> rowSize{1, 2, 3, 2, 1};
    std::vector<Ball> balls;
    const Vec2 apex = footSpot(table);
    const double R = table.ballRadius;
    int n = 0;
    for (int row = 0; row < 5; ++row) {
        const int size = rowSize[static_cast<std::size_t>(row)];
        for (int k = 0; k < size; ++k) {
            const Vec2 p = apex + Vec2(std::sqrt(3.0) * R * row, R * (2.0 * k - (size - 1)));
            balls.push_back(makeBall(table, std::to_string(order[static_cast<std::size_t>(n++)]), p));
        }
    }
    return balls;
}

std::vector<Ball> cradleLine(const Table& table, int count, const Vec2& first)
{
    std::vector<Ball> balls;
    for (int i = 0; i < count; ++i)
        balls.push_back(makeBall(table, std::to_string(i + 1), first + Vec2(2.0 * table.ballRadius * i, 0.0)));
    return balls;
}

Setup breakSetup(double cueSpeed)
{
    Setup setup;
    setup.name = "8-ball break";
    setup.table.kind = TableKind::Pool9ft;
    const Table table = makeTable(setup.table);
    setup.balls.push_back(makeBall(table, "cue", headSpot(table)));
    for (Ball& b : rack8Ball(table)) setup.balls.push_back(std::move(b));
    CueStrike shot;
    shot.ball = "cue";
    shot.speed = cueSpeed;
    setup.shot = shot;
    return setup;
}

}  // namespace cuelab
