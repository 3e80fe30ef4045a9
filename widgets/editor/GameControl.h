#pragma once
// The game in the Shot dock (issue 43): whose rules judge the shot (none, 8-ball, 9-ball, 10-ball,
// snooker, three-cushion) and the state a single shot needs from the game (8-ball: the striker's
// group; snooker: the ball on). Each change is an undoable edit of the setup's `game`; a game the
// balls do not fit is refused with the validator's message (the ball named), like any edit.

#include <QWidget>

class QComboBox;

namespace cuelab {

class Document;

class GameControl : public QWidget {
    Q_OBJECT
public:
    explicit GameControl(Document* document, QWidget* parent = nullptr);

    QComboBox* rulesBox() const { return rules_; }
    QComboBox* stateBox() const { return state_; }

private:
    void refresh();
    void commitRules();
    void commitState();

    Document* document_;
    QComboBox* rules_;
    QComboBox* state_;  // the group (8-ball) or the ball on (snooker); hidden for the other games
    bool refreshing_ = false;
};

}  // namespace cuelab
