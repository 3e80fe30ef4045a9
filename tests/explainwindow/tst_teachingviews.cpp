// Issue 22's teaching and coaching views in the window, under Xvfb: the Shot dock's Aim at fields
// (heading from a cut of an object ball, undoable) and readouts (first contact, the ball's launch),
// the Inspector's aim and centre-of-mass rows, View > Overlays > Aim Line and Ghost Ball, View >
// Centre-of-Mass Frame (arrows, paths, the Explain dock's momenta diagram), the Δp arrows and the
// Plots dock's momentum and energy-parts choices. Every number is checked against core/aim, the
// computation behind the CLI and the core tests too.

#include "MainWindow.h"
#include "editor/AimControl.h"
#include "editor/AimLayer.h"
#include "editor/Document.h"
#include "editor/InspectorPanel.h"
#include "editor/Selection.h"
#include "editor/ShotPanel.h"
#include "explain/ConservationWidget.h"
#include "explain/EventArrows.h"
#include "explain/ExplainPanel.h"
#include "explain/FrameArrows.h"
#include "plots/PlotsPanel.h"
#include "view/TableView.h"

#include "Aim.h"
#include "Frames.h"

#include <QAction>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QLabel>
#include <QMenu>
#include <QUndoStack>
#include <QtTest>

using namespace cuelab;

namespace {

const QString kHalfBall = QStringLiteral(CUELAB_SOURCE_DIR "/resources/examples/half-ball-cut.json");

int firstBallBall(const SimulationResult& r)
{
    for (std::size_t i = 0; i < r.events.size(); ++i)
        if (r.events[i].kind == EventKind::BallBall) return int(i);
    return -1;
}

const ViewLayer* layerOf(TableView* view, const QString& name)
{
    const auto it = view->layers().find(name);
    return it == view->layers().end() ? nullptr : &it->second;
}

}  // namespace

class TestTeachingViews : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void init()
    {
        window_ = new MainWindow;
        window_->resize(1600, 1000);
        window_->show();
        QVERIFY(QTest::qWaitForWindowExposed(window_));
        QVERIFY(window_->openFile(kHalfBall));
        window_->document()->waitForResult();
    }
    void cleanup()
    {
        window_->document()->undoStack()->setClean();
        delete window_;
        window_ = nullptr;
    }

    // "Aim at the 1, cut 30° left": the heading becomes core/aim's, one undo step; the readout shows
    // the simulated first contact; the launch readout the struck ball's speed after the strike.
    void aimAtAnObjectBall()
    {
        auto* aim = window_->shotPanel()->findChild<AimControl*>();
        QVERIFY(aim);
        QCOMPARE(aim->objectBall()->currentText(), QStringLiteral("1"));
        QVERIFY(!aim->cutAngle()->toolTip().isEmpty() && aim->cutAngle()->toolTip().contains(QStringLiteral("degrees")));
        const Setup before = window_->document()->setup();
        const double oldHeading = before.shot->headingDeg;
        const Ball& cue = before.balls[0];
        const Ball& one = before.balls[1];
        aim->cutSide()->setCurrentIndex(1);  // right
        aim->cutAngle()->setValue(45.0);
        aim->cutAngle()->editingFinished();
        const std::optional<double> expected =
            aim::headingForCut(cue.state.position, one.state.position, cue.radius, one.radius, 45.0, aim::CutSide::Right);
        QVERIFY(expected);
        QCOMPARE(window_->document()->setup().shot->headingDeg, *expected);
        QVERIFY(window_->document()->undoStack()->undoText().contains(QStringLiteral("cut")));
        window_->document()->waitForResult();
        int other = -1;
        const auto g = aim::firstContact(*window_->document()->result(), nullptr, &other);
        QVERIFY(g && other == 1);
        QVERIFY2(aim->firstContact()->text().contains(QStringLiteral("right")), qPrintable(aim->firstContact()->text()));
        QVERIFY(aim->firstContact()->text().contains(QString::number(g->ballFraction, 'f', 2)));
        window_->document()->undoStack()->undo();
        QCOMPARE(window_->document()->setup().shot->headingDeg, oldHeading);
        // Back at the example's heading the field reads the cut the straight cue line makes.
        QVERIFY2(std::abs(aim->cutAngle()->value() - 30.0) < 0.05, qPrintable(QString::number(aim->cutAngle()->value())));
        QCOMPARE(aim->cutSide()->currentIndex(), 0);  // left
        window_->document()->waitForResult();
        auto* launch = window_->shotPanel()->findChild<QLabel*>(QStringLiteral("launchReadout"));
        QVERIFY(launch && !launch->toolTip().isEmpty());
        const auto l = aim::launchOf(*window_->document()->result());
        QVERIFY(l);
        QVERIFY2(launch->text().contains(QString::number(l->speed, 'f', 2)), qPrintable(launch->text()));
    }

    void inspectorShowsAimAndFrame()
    {
        const auto r = window_->document()->result();
        const int hit = firstBallBall(*r);
        window_->selection()->selectEvent(hit);
        const auto g = aim::contactOfEvent(*r, hit);
        QVERIFY(g);
        InspectorPanel* inspector = window_->inspector();
        QVERIFY2(inspector->value(QStringLiteral("Cut angle")).startsWith(QStringLiteral("30.00")),
                 qPrintable(inspector->value(QStringLiteral("Cut angle"))));
        QCOMPARE(inspector->value(QStringLiteral("Ball fraction")), QString::number(g->ballFraction, 'f', 3));
        QVERIFY(!inspector->value(QStringLiteral("Centre-of-mass frame")).isEmpty());
        QVERIFY(!inspector->value(QStringLiteral("Lost to the cloth")).isEmpty());
    }

    void aimOverlay()
    {
        auto* toggle = window_->findChild<QAction*>(QStringLiteral("aimOverlayAction"));
        QVERIFY(toggle && toggle->isCheckable() && !toggle->shortcut().isEmpty());
        const auto* overlays = window_->findChild<QMenu*>(QStringLiteral("overlaysMenu"));
        QVERIFY(overlays && overlays->actions().contains(toggle));
        TableView* view = window_->tableView();
        toggle->setChecked(false);
        QVERIFY(!layerOf(view, kAimLayer));
        toggle->setChecked(true);
        const ViewLayer* layer = layerOf(view, kAimLayer);
        QVERIFY(layer);
        const auto g = aim::firstContact(*window_->document()->result());
        QCOMPARE(layer->ghosts.size(), std::size_t(1));
        QCOMPARE(layer->ghosts[0].positions[0], g->ghostBall);
        QCOMPARE(layer->polylines.size(), std::size_t(2));
        QVERIFY(layer->polylines[1].label.contains(QStringLiteral("0.50")));
        toggle->setChecked(false);
        QVERIFY(!layerOf(view, kAimLayer));
    }

    // The frame toggle: p* arrows equal and opposite, the centre of mass and its paths, the dock's
    // diagram; Δp arrows J and −J in both frames.
    void centreOfMassFrame()
    {
        auto* toggle = window_->findChild<QAction*>(QStringLiteral("centreOfMassFrameAction"));
        QVERIFY(toggle && toggle->isCheckable() && !toggle->shortcut().isEmpty() && !toggle->toolTip().isEmpty());
        auto* arrows = window_->findChild<QAction*>(QStringLiteral("collisionArrowsAction"));
        QVERIFY(arrows);
        arrows->setChecked(true);
        toggle->setChecked(false);
        const auto r = window_->document()->result();
        const int hit = firstBallBall(*r);
        window_->selection()->selectEvent(hit);
        TableView* view = window_->tableView();
        auto* panel = window_->findChild<ExplainPanel*>(QStringLiteral("explainPanel"));
        QVERIFY(panel && !panel->conservation()->centreOfMassFrame());
        QVERIFY(layerOf(view, kEventArrowsLayer));
        QVERIFY(!layerOf(view, kCentreOfMassLayer));
        const ViewLayer* changes = layerOf(view, kMomentumChangeLayer);
        QVERIFY(changes && changes->arrows.size() == 2);
        const Vec3 j0 = changes->arrows[0].to - changes->arrows[0].from, j1 = changes->arrows[1].to - changes->arrows[1].from;
        QVERIFY2((j0 + j1).norm() < 1e-12, qPrintable(QString::number((j0 + j1).norm())));
        QVERIFY((j0.head<2>() - r->events[std::size_t(hit)].impulse.head<2>() * kArrowMetresPerNewtonSecond).norm() < 1e-12);

        toggle->setChecked(true);
        QVERIFY(panel->conservation()->centreOfMassFrame());
        const ViewLayer* layer = layerOf(view, kEventArrowsLayer);
        QVERIFY(layer);
        // The momenta before: p*_a + p*_b = 0 (the first two arrows: the cue ball's and the 1's p*
        // before, or the cue's p* before and after when the 1 rests... both balls move in this frame).
        std::vector<Vec3> before;
        for (const LayerArrow& a : layer->arrows)
            if (a.label.startsWith(QStringLiteral("p* "))) before.push_back(a.to - a.from);
        QCOMPARE(before.size(), std::size_t(2));
        QVERIFY2((before[0] + before[1]).norm() < 1e-12, qPrintable(QString::number((before[0] + before[1]).norm())));
        const ViewLayer* frame = layerOf(view, kCentreOfMassLayer);
        QVERIFY(frame);
        QCOMPARE(frame->polylines.size(), std::size_t(2));
        QCOMPARE(frame->markers.size(), std::size_t(1));
        // Δp is the same in either frame.
        changes = layerOf(view, kMomentumChangeLayer);
        QVERIFY(changes && (changes->arrows[0].to - changes->arrows[0].from - j0).norm() < 1e-12);
        toggle->setChecked(false);
        QVERIFY(!layerOf(view, kCentreOfMassLayer));
        QVERIFY(!panel->conservation()->centreOfMassFrame());
    }

    void plotsChoices()
    {
        auto* plots = window_->findChild<PlotsPanel*>(QStringLiteral("plotsPanel"));
        QVERIFY(plots);
        // Every choice, for one ball and for all, from the selected collision's time.
        window_->selection()->selectEvent(firstBallBall(*window_->document()->result()));
        for (bool all : {false, true}) {
            plots->setAllBalls(all);
            for (PlotsPanel::Plot p : {PlotsPanel::Plot::Speed, PlotsPanel::Plot::Momentum, PlotsPanel::Plot::EnergyParts,
                                       PlotsPanel::Plot::Energy, PlotsPanel::Plot::Height})
                plots->setPlot(p);
        }
        auto* box = plots->findChild<QComboBox*>(QStringLiteral("plotKind"));
        QVERIFY(box);
        plots->setAllBalls(false);
        for (int k = 0; k < box->count(); ++k) box->setCurrentIndex(k);
        QCOMPARE(plots->plot(), PlotsPanel::Plot::Height);  // the last choice
        QStringList heights;
        for (const PlotsPanel::Line& l : plots->lines()) heights << l.name;
        QVERIFY2(heights.size() == 2 && heights[0].endsWith(QLatin1String(" z")) && heights[1].endsWith(QLatin1String(" vz")),
                 qPrintable(heights.join(", ")));
        plots->setAllBalls(true);
        plots->setPlot(PlotsPanel::Plot::Momentum);
        QStringList names;
        for (const PlotsPanel::Line& l : plots->lines()) names << l.name;
        QVERIFY2(names.contains(QStringLiteral("cue |p|")) && names.contains(QStringLiteral("|total p|")), qPrintable(names.join(", ")));
        plots->setPlot(PlotsPanel::Plot::EnergyParts);
        names.clear();
        for (const PlotsPanel::Line& l : plots->lines()) names << l.name;
        QCOMPARE(names.size(), 4);
        QVERIFY(names.contains(QStringLiteral("lost to the cloth")));
    }

private:
    MainWindow* window_ = nullptr;
};

QTEST_MAIN(TestTeachingViews)
#include "tst_teachingviews.moc"
