#pragma once
// Beside the cue's speed in the Shot dock: what the strike gave the ball (issue 22), its speed and
// spin just after the cue strike, read off the simulation (aim::launchOf, the cue-strike event's
// after-state). A coach thinks in ball speed; the Speed field is the cue's.

#include <QLabel>

namespace cuelab {

class Document;

class LaunchReadout : public QLabel {
    Q_OBJECT
public:
    explicit LaunchReadout(Document* document, QWidget* parent = nullptr);

private:
    void refresh();
    Document* document_;
};

}  // namespace cuelab
