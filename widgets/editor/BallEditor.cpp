#include "BallEditor.h"

#include "Document.h"
#include "Quantities.h"

#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace cuelab {

namespace {

constexpr int kFirstNumber = static_cast<int>(BallProperty::X);

std::size_t slot(BallProperty p) { return static_cast<std::size_t>(static_cast<int>(p) - kFirstNumber); }

double valueOf(const Ball& b, BallProperty p)
{
    switch (p) {
    case BallProperty::X: return b.state.position.x();
    case BallProperty::Y: return b.state.position.y();
    case BallProperty::Vx: return b.state.velocity.x();
    case BallProperty::Vy: return b.state.velocity.y();
    case BallProperty::Wx: return b.state.spin.x();
    case BallProperty::Wy: return b.state.spin.y();
    case BallProperty::Wz: return b.state.spin.z();
    case BallProperty::Radius: return b.radius;
    case BallProperty::Mass: return b.mass;
    case BallProperty::Id: break;
    }
    return 0.0;
}

void setValue(Ball& b, BallProperty p, double v)
{
    switch (p) {
    case BallProperty::X: b.state.position.x() = v; break;
    case BallProperty::Y: b.state.position.y() = v; break;
    case BallProperty::Vx: b.state.velocity.x() = v; break;
    case BallProperty::Vy: b.state.velocity.y() = v; break;
    case BallProperty::Wx: b.state.spin.x() = v; break;
    case BallProperty::Wy: b.state.spin.y() = v; break;
    case BallProperty::Wz: b.state.spin.z() = v; break;
    case BallProperty::Radius: b.radius = v; break;
    case BallProperty::Mass: b.mass = v; break;
    case BallProperty::Id: break;
    }
}

QString undoText(BallProperty p, const QString& id)
{
    switch (p) {
    case BallProperty::X:
    case BallProperty::Y: return QObject::tr("Move ball %1").arg(id);
    case BallProperty::Vx:
    case BallProperty::Vy: return QObject::tr("Set the velocity of ball %1").arg(id);
    case BallProperty::Wx:
    case BallProperty::Wy:
    case BallProperty::Wz: return QObject::tr("Set the spin of ball %1").arg(id);
    case BallProperty::Radius: return QObject::tr("Set the radius of ball %1").arg(id);
    case BallProperty::Mass: return QObject::tr("Set the mass of ball %1").arg(id);
    case BallProperty::Id: break;
    }
    return QObject::tr("Rename ball %1").arg(id);
}

}  // namespace

BallEditor::BallEditor(Document* document, QWidget* parent) : QWidget(parent), document_(document)
{
    setProperty("saysRefusals", true);  // the window's refusal note leaves its fields to it
    box_ = new QGroupBox(this);
    id_ = new QLineEdit(box_);
    id_->setToolTip(tr("The ball's id: unique, not empty; the shot, the events and the command line name the ball by it"));
    id_->setClearButtonEnabled(false);

    const auto spin = [this](BallProperty p, const SpinBoxSpec& spec) {
        // Its own minimum: wide enough for its whole range with its unit (never a cut "0.0000 m").
        QDoubleSpinBox* box = makeSpinBox(spec, box_);
        numbers_[slot(p)] = box;
        connect(box, &QDoubleSpinBox::valueChanged, this, [this, p] { commit(p); });
        // A run of arrow clicks is one step; leaving the field ends it.
        connect(box, &QDoubleSpinBox::editingFinished, document_, &Document::endMerge);
    };
    spin(BallProperty::X, {-10.0, 10.0, 4, 0.001, tr("m"), tr("Position of the centre along the length at t = 0, in metres")});
    spin(BallProperty::Y, {-10.0, 10.0, 4, 0.001, tr("m"), tr("Position of the centre across the width at t = 0, in metres")});
    spin(BallProperty::Vx, {-50.0, 50.0, 3, 0.05, tr("m/s"), tr("Velocity along the length at t = 0, in m/s (before any cue strike)")});
    spin(BallProperty::Vy, {-50.0, 50.0, 3, 0.05, tr("m/s"), tr("Velocity across the width at t = 0, in m/s (before any cue strike)")});
    spin(BallProperty::Wx, {-1000.0, 1000.0, 2, 1.0, tr("rad/s"), tr("Angular velocity about the length axis x at t = 0, in rad/s")});
    spin(BallProperty::Wy, {-1000.0, 1000.0, 2, 1.0, tr("rad/s"), tr("Angular velocity about the width axis y at t = 0, in rad/s (rolling along +x: wy = vx / R)")});
    spin(BallProperty::Wz, {-1000.0, 1000.0, 2, 1.0, tr("rad/s"), tr("Angular velocity about the vertical axis z at t = 0, in rad/s (side spin)")});
    spin(BallProperty::Radius, {0.0, 0.5, 6, 0.0005, tr("m"), tr("Radius of the ball in metres (pool 0.028575 m, snooker 0.02625 m, carom 0.03075 m)")});
    spin(BallProperty::Mass, {0.0, 5.0, 6, 0.005, tr("kg"), tr("Mass of the ball in kg (pool 0.170 kg, snooker 0.140 kg, carom 0.210 kg)")});

    problem_ = new QLabel(this);
    problem_->setWordWrap(true);
    problem_->setTextFormat(Qt::PlainText);
    problem_->setForegroundRole(QPalette::BrightText);
    problem_->setAutoFillBackground(true);
    {
        QPalette p = problem_->palette();
        p.setColor(QPalette::Window, QColor(0xb0, 0x30, 0x20));
        p.setColor(QPalette::BrightText, Qt::white);
        problem_->setPalette(p);
    }
    problem_->setMargin(4);
    problem_->hide();

    auto* grid = new QGridLayout(box_);
    grid->setContentsMargins(6, 4, 6, 4);
    grid->setHorizontalSpacing(4);
    grid->setVerticalSpacing(3);
    const auto label = [this](const QString& text, QWidget* buddy) {
        auto* l = new QLabel(text, box_);
        l->setBuddy(buddy);
        l->setToolTip(buddy->toolTip());
        return l;
    };
    const auto number = [this](BallProperty p) { return numbers_[slot(p)]; };
    // One field a row, its axis beside it: the editor fits a side column of 240 px (Edit at 800x600)
    // with every value whole, each box as wide as its range and unit ask.
    grid->addWidget(label(tr("&Id"), id_), 0, 0);
    grid->addWidget(id_, 0, 1, 1, 2);
    int row = 1;
    const auto vector = [&](const QString& name, std::initializer_list<BallProperty> components) {
        const char* axes[] = {"x", "y", "z"};
        int k = 0;
        for (BallProperty p : components) {
            if (k == 0) grid->addWidget(label(name, number(p)), row, 0);
            auto* axis = new QLabel(QString::fromLatin1(axes[k++]), box_);
            axis->setToolTip(number(p)->toolTip());
            grid->addWidget(axis, row, 1);
            grid->addWidget(number(p), row++, 2);
        }
    };
    vector(tr("Position"), {BallProperty::X, BallProperty::Y});
    vector(tr("Velocity"), {BallProperty::Vx, BallProperty::Vy});
    vector(tr("Spin"), {BallProperty::Wx, BallProperty::Wy, BallProperty::Wz});
    grid->addWidget(label(tr("Radius"), number(BallProperty::Radius)), row, 0);
    grid->addWidget(number(BallProperty::Radius), row++, 1, 1, 2);
    grid->addWidget(label(tr("Mass"), number(BallProperty::Mass)), row, 0);
    grid->addWidget(number(BallProperty::Mass), row++, 1, 1, 2);
    grid->setColumnStretch(2, 1);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(box_);
    layout->addWidget(problem_);

    connect(id_, &QLineEdit::editingFinished, this, [this] { commit(BallProperty::Id); });
    connect(document_, &Document::setupChanged, this, &BallEditor::refresh);
    connect(document_, &Document::documentReplaced, this, [this] { setBall(-1); });
    connect(document_, &Document::editRefused, this, [this](const QString& message) {
        if (committing_) showProblem(message);
    });
    refresh();
}

QDoubleSpinBox* BallEditor::spinBox(BallProperty property) const
{
    if (property == BallProperty::Id) return nullptr;
    return numbers_[slot(property)];
}

void BallEditor::setBall(int index)
{
    if (index == ball_) return;
    ball_ = index;
    showProblem(QString());
    refresh();
}

void BallEditor::refresh()
{
    const std::vector<Ball>& balls = document_->setup().balls;
    if (ball_ >= static_cast<int>(balls.size())) ball_ = -1;
    const bool any = ball_ >= 0;
    refreshing_ = true;
    {
        const QSignalBlocker block(id_);
        id_->setText(any ? QString::fromStdString(balls[static_cast<std::size_t>(ball_)].id) : QString());
    }
    for (int p = kFirstNumber; p <= static_cast<int>(BallProperty::Mass); ++p) {
        QDoubleSpinBox* box = numbers_[static_cast<std::size_t>(p - kFirstNumber)];
        const QSignalBlocker block(box);
        box->setValue(any ? valueOf(balls[static_cast<std::size_t>(ball_)], static_cast<BallProperty>(p)) : 0.0);
    }
    refreshing_ = false;
    box_->setEnabled(any);
    box_->setTitle(any ? tr("Ball %1 at t = 0").arg(QString::fromStdString(balls[static_cast<std::size_t>(ball_)].id))
                       : tr("No ball selected"));
}

void BallEditor::commit(BallProperty property)
{
    if (refreshing_ || ball_ < 0 || ball_ >= static_cast<int>(document_->setup().balls.size())) return;
    Ball ball = document_->setup().balls[static_cast<std::size_t>(ball_)];
    const QString id = QString::fromStdString(ball.id);
    if (property == BallProperty::Id) {
        const std::string renamed = id_->text().trimmed().toStdString();
        if (renamed == ball.id) return;
        ball.id = renamed;
    } else {
        QDoubleSpinBox* box = numbers_[slot(property)];
        // Only the edited value changes; a value left as it was keeps its full precision.
        if (formatNumber(box->value(), box->decimals()) == formatNumber(valueOf(ball, property), box->decimals())) return;
        setValue(ball, property, box->value());
    }
    committing_ = true;
    const bool applied = document_->setBall(ball_, ball, property == BallProperty::Id
                                                             ? tr("Rename ball %1 to %2").arg(id, id_->text().trimmed())
                                                             : undoText(property, id),
                                            static_cast<int>(property));
    committing_ = false;
    if (applied) showProblem(QString());
    else refresh();  // refused: show the ball as it is (the reason stays shown)
    if (property == BallProperty::Id) document_->endMerge();
}

void BallEditor::showProblem(const QString& message)
{
    problem_->setText(message);
    problem_->setVisible(!message.isEmpty());
}

}  // namespace cuelab
