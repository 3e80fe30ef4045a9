// The document's ball edits (Document.h): move, set, add, remove and copy a ball, and rack the
// table, each one undoable step (or, for a rack, one macro) through Document::edit.

#include "Document.h"

#include "LegalPlacement.h"
#include "LegalSetup.h"

#include <QUndoStack>

namespace cuelab {

namespace {

// The smallest positive integer id that is not taken ("1", "2", ...).
std::string freeId(const Setup& setup)
{
    for (int n = 1;; ++n) {
        const std::string id = std::to_string(n);
        bool taken = false;
        for (const Ball& b : setup.balls) taken = taken || b.id == id;
        if (!taken) return id;
    }
}

// A free spot near `preferred` for a new ball of radius `radius`, clear of the others by `gap`.
std::optional<Vec2> freeSpot(const Setup& setup, const Vec2& preferred, double radius, double gap)
{
    // The document's setup is always legal, so its table can be built.
    return nearestLegalSpot(makeTable(setup.table), setup.balls, radius, preferred, gap, -1);
}

}  // namespace

bool Document::moveBall(int index, const Vec2& position)
{
    if (index < 0 || index >= static_cast<int>(setup_.balls.size())) return false;
    Setup after = setup_;
    Ball& ball = after.balls[static_cast<std::size_t>(index)];
    ball.state.position = position;
    return editBall(index, tr("Move ball %1").arg(QString::fromStdString(ball.id)), after, {MergeKind::MoveBall, index});
}

bool Document::setBall(int index, const Ball& ball, const QString& text, int field)
{
    if (index < 0 || index >= static_cast<int>(setup_.balls.size())) return false;
    Setup after = setup_;
    const std::string oldId = after.balls[static_cast<std::size_t>(index)].id;
    Ball& changed = after.balls[static_cast<std::size_t>(index)];
    changed = ball;
    // The motion state follows the numbers (as the loader classifies a file's ball).
    changed.state.motion = classify(changed.state, changed.radius);
    changed.state.pocket = -1;
    if (after.shot && after.shot->ball == oldId) after.shot->ball = ball.id;  // a rename keeps the shot
    return editBall(index, text, after, {MergeKind::BallField, index * 16 + field});
}

bool Document::setBallVelocity(int index, const Vec2& velocity)
{
    if (index < 0 || index >= static_cast<int>(setup_.balls.size())) return false;
    Ball ball = setup_.balls[static_cast<std::size_t>(index)];
    ball.state.velocity = velocity;
    return setBall(index, ball, tr("Set the velocity of ball %1").arg(QString::fromStdString(ball.id)),
                   static_cast<int>(BallProperty::Vx));
}

int Document::addBall()
{
    const Table table = makeTable(setup_.table);
    const std::optional<Vec2> spot = freeSpot(setup_, Vec2(0.5 * table.length, 0.5 * table.width), table.ballRadius, kEditorGap);
    if (!spot) {
        emit editRefused(tr("There is no free place on the table for another ball."));
        return -1;
    }
    Setup after = setup_;
    Ball ball;
    ball.id = freeId(setup_);
    ball.radius = table.ballRadius;
    ball.mass = table.ballMass;
    ball.state.position = *spot;
    after.balls.push_back(ball);
    if (!edit(tr("Add ball %1").arg(QString::fromStdString(ball.id)), after)) return -1;
    return static_cast<int>(setup_.balls.size()) - 1;
}

bool Document::removeBall(int index)
{
    if (index < 0 || index >= static_cast<int>(setup_.balls.size())) return false;
    Setup after = setup_;
    const std::string id = after.balls[static_cast<std::size_t>(index)].id;
    after.balls.erase(after.balls.begin() + index);
    // The shot must name a ball: it moves to the first ball left, or goes when none is.
    if (after.shot && after.shot->ball == id) {
        if (after.balls.empty()) after.shot.reset();
        else after.shot->ball = after.balls.front().id;
    }
    return edit(tr("Remove ball %1").arg(QString::fromStdString(id)), after);
}

int Document::duplicateBall(int index)
{
    if (index < 0 || index >= static_cast<int>(setup_.balls.size())) return -1;
    Ball copy = setup_.balls[static_cast<std::size_t>(index)];
    const std::optional<Vec2> spot = freeSpot(setup_, copy.state.position, copy.radius, kEditorGap);
    if (!spot) {
        emit editRefused(tr("There is no free place on the table for another ball."));
        return -1;
    }
    const std::string original = copy.id;
    copy.id = freeId(setup_);
    copy.state.position = *spot;
    Setup after = setup_;
    after.balls.push_back(copy);
    if (!edit(tr("Duplicate ball %1").arg(QString::fromStdString(original)), after)) return -1;
    return static_cast<int>(setup_.balls.size()) - 1;
}

bool Document::applyRack(RackPreset preset)
{
    const std::vector<Ball> rack = rackBalls(preset, makeTable(setup_.table));
    // One undo step made of the single-ball edits: clear the table, then place every ball.
    Setup cleared = setup_;
    cleared.balls.clear();
    cleared.shot.reset();
    Setup placed = cleared;
    for (const Ball& b : rack) placed.balls.push_back(b);
    placed.shot = setup_.shot.value_or(CueStrike{});
    placed.shot->ball = rack.front().id;
    QString error;
    if (!validate(placed, &error)) {
        emit editRefused(error);
        return false;
    }
    undoStack_->beginMacro(tr("Rack: %1").arg(rackName(preset)));
    edit(tr("Clear the table"), cleared);
    Setup partial = cleared;
    for (const Ball& b : rack) {
        partial.balls.push_back(b);
        edit(tr("Place ball %1").arg(QString::fromStdString(b.id)), partial);
    }
    edit(tr("Aim at the rack"), placed);
    undoStack_->endMacro();
    return true;
}

}  // namespace cuelab
