#pragma once
// The tip a new user sees above the table view on the first start: where the examples are, how to
// play and step, and where every shortcut is listed. Closing it (or any later start) hides it for
// good; Help > Show First-Start Tip brings it back.

#include <QFrame>

namespace cuelab {

class FirstStartTip : public QFrame {
    Q_OBJECT
public:
    explicit FirstStartTip(QWidget* parent = nullptr);

    // Whether the tip is still to be shown (the setting "help/firstStartTipSeen" is not set).
    static bool pending();
    // Shows it again, and forgets that it was seen.
    void showAgain();

private:
    void dismiss();
};

}  // namespace cuelab
