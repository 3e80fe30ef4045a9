#pragma once
// The tip a new user sees over the top of the table view on the first start: where the examples
// are, how to play and step, where the user guide and every shortcut are. Closing it (or any later
// start) hides it for good; Help > Show First-Start Tip brings it back. It lies over its parent (the
// table view), across its width at the top, and follows its size: the view keeps its whole height.

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

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    void dismiss();
    void place();
};

}  // namespace cuelab
