#pragma once
// The Balls dock: every ball with its set-up position (editable, in metres) and its state, position
// and speed at the current time; add, remove, duplicate, and rack presets; under the list, every
// property of the selected ball (BallEditor).

#include <QWidget>

class QAction;
class QMenu;
class QTableWidget;

namespace cuelab {

class BallEditor;
class Document;

class BallsPanel : public QWidget {
    Q_OBJECT
public:
    explicit BallsPanel(Document* document, QWidget* parent = nullptr);

    enum Column { IdColumn, XColumn, YColumn, StateColumn, PositionColumn, SpeedColumn, ColumnCount };

    QTableWidget* table() const { return table_; }
    QAction* addBallAction() const { return add_; }
    QAction* removeBallAction() const { return remove_; }
    QAction* duplicateBallAction() const { return duplicate_; }
    QMenu* rackMenu() const { return rackMenu_; }
    BallEditor* editor() const { return editor_; }
    int selectedBall() const;

public slots:
    void setTime(double seconds);
    void setSelectedBall(int index);  // -1 = none; does not emit ballSelected

signals:
    void ballSelected(int index);

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;  // the table's width: fitColumns()

private:
    void rebuild();         // rows from the setup
    void refreshMotion();   // the columns that depend on the time
    void fitColumns();
    void commitItem(int row, int column);
    void updateActions();

    Document* document_;
    QTableWidget* table_;
    BallEditor* editor_;
    QAction* add_;
    QAction* remove_;
    QAction* duplicate_;
    QMenu* rackMenu_;
    double time_ = 0.0;  // s
    bool refreshing_ = false;
};

}  // namespace cuelab
