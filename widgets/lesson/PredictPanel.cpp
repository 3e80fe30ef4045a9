#include "PredictPanel.h"

#include "i18n/UiNumbers.h"

#include "PredictSession.h"
#include "PredictionText.h"
#include "editor/Document.h"
#include "editor/ResultFeed.h"
#include "editor/Selection.h"
#include "i18n/DisplayNames.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace cuelab {

namespace {

enum QuestionColumn { StopsBeforeColumn = 0, BallsColumn, PromptColumn, QuestionColumns };
enum ResultColumn { QuestionColumn = 0, BallColumn, GuessColumn, ActualColumn, ErrorColumn, ScoreColumn, ResultColumns };

QTableWidgetItem* readOnly(const QString& text)
{
    auto* item = new QTableWidgetItem(text);
    item->setFlags(item->flags() & ~Qt::ItemIsEditable);
    return item;
}

}  // namespace

PredictPanel::PredictPanel(Document* document, Playback* playback, Selection* selection, TableView* view, QWidget* parent)
    : QWidget(parent), document_(document), selection_(selection)
{
    session_ = new PredictSession(document, playback, view, this);

    auto* intro = new QLabel(tr("Predict, then reveal: the shot stops before each question's event; drag from each ball "
                                "where it will go, then reveal where it went."),
                             this);
    intro->setWordWrap(true);
    questions_ = new QTableWidget(0, QuestionColumns, this);
    questions_->setObjectName(QStringLiteral("predictQuestions"));
    questions_->setHorizontalHeaderLabels({tr("Stops before"), tr("Balls"), tr("Question")});
    questions_->horizontalHeaderItem(StopsBeforeColumn)->setToolTip(tr("The event the shot stops before (set when the question is added)"));
    questions_->horizontalHeaderItem(BallsColumn)->setToolTip(tr("The ids of the balls to predict, separated by commas; empty: the event's own balls"));
    questions_->horizontalHeaderItem(PromptColumn)->setToolTip(tr("What the student reads; empty: \"Where will each ball go?\""));
    questions_->horizontalHeader()->setStretchLastSection(true);
    questions_->verticalHeader()->setVisible(false);
    questions_->setSelectionBehavior(QAbstractItemView::SelectRows);
    questions_->setSelectionMode(QAbstractItemView::SingleSelection);
    questions_->setMinimumHeight(90);

    add_ = new QPushButton(tr("Add Question"), this);
    add_->setObjectName(QStringLiteral("predictAdd"));
    add_->setToolTip(tr("Ask before the event selected in Events (the first collision when none is); one undo step"));
    remove_ = new QPushButton(tr("Remove"), this);
    remove_->setObjectName(QStringLiteral("predictRemove"));
    remove_->setToolTip(tr("Remove the selected question; one undo step"));
    start_ = new QPushButton(tr("Start"), this);
    start_->setObjectName(QStringLiteral("predictStart"));
    start_->setToolTip(tr("Play the shot from the start and stop before each question (without questions: before the "
                          "first collision)"));
    reveal_ = new QPushButton(tr("Reveal"), this);
    reveal_->setObjectName(QStringLiteral("predictReveal"));
    reveal_->setToolTip(tr("Show where each ball went beside your guess, with the angle between them in degrees, and play on"));
    // Two rows, so that the dock stays narrow: the teacher's buttons, then the student's.
    auto* edits = new QHBoxLayout;
    edits->addWidget(add_);
    edits->addWidget(remove_);
    edits->addStretch();
    auto* mode = new QHBoxLayout;
    mode->addWidget(start_);
    mode->addWidget(reveal_);
    mode->addStretch();

    status_ = new QLabel(this);
    status_->setObjectName(QStringLiteral("predictStatus"));
    status_->setWordWrap(true);
    status_->setTextFormat(Qt::PlainText);
    status_->setStyleSheet(QStringLiteral("QLabel { padding: 4px; }"));
    results_ = new QTableWidget(0, ResultColumns, this);
    results_->setObjectName(QStringLiteral("predictResults"));
    results_->setHorizontalHeaderLabels({tr("#"), tr("Ball"), tr("Your guess"), tr("Went"), tr("Error"), tr("Score")});
    results_->horizontalHeaderItem(GuessColumn)->setToolTip(tr("Your direction, in degrees (0° = along the table's length, counter-clockwise)"));
    results_->horizontalHeaderItem(ActualColumn)->setToolTip(tr("Where the ball went, in degrees: its direction once it stops sliding, "
                                                          "or before its next collision"));
    results_->horizontalHeaderItem(ErrorColumn)->setToolTip(tr("The angle between your guess and where it went, in degrees (0° to 180°)"));
    results_->horizontalHeaderItem(ScoreColumn)->setToolTip(tr("100 % for a perfect guess, falling to 0 % at 90° off; a right \"stays\" scores 100 %"));
    results_->setEditTriggers(QAbstractItemView::NoEditTriggers);
    results_->verticalHeader()->setVisible(false);
    results_->horizontalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    results_->setMinimumHeight(90);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addWidget(intro);
    layout->addWidget(questions_, 1);
    layout->addLayout(edits);
    layout->addLayout(mode);
    layout->addWidget(status_);
    layout->addWidget(results_, 1);

    connect(add_, &QPushButton::clicked, this, &PredictPanel::addQuestion);
    connect(remove_, &QPushButton::clicked, this, &PredictPanel::removeQuestion);
    connect(start_, &QPushButton::clicked, this, &PredictPanel::toggleSession);
    connect(reveal_, &QPushButton::clicked, session_, &PredictSession::reveal);
    connect(questions_, &QTableWidget::cellChanged, this, &PredictPanel::commitCell);
    connect(questions_, &QTableWidget::itemSelectionChanged, this, [this] { remove_->setEnabled(questions_->currentRow() >= 0); });
    connect(document_, &Document::setupChanged, this, &PredictPanel::loadQuestions);
    connect(document_, &Document::documentReplaced, this, &PredictPanel::loadQuestions);
    ResultFeed::follow(document_, this, [this] { loadQuestions(); });
    connect(session_, &PredictSession::stateChanged, this, &PredictPanel::refreshMode);
    connect(session_, &PredictSession::predictionsChanged, this, &PredictPanel::refreshMode);
    connect(session_, &PredictSession::revealedChanged, this, &PredictPanel::refreshResults);
    loadQuestions();
    refreshMode();
}

void PredictPanel::loadQuestions()
{
    const auto& questions = document_->setup().questions;
    // The whole run names the events, except those a waiting question hides (Document::setHorizon):
    // "#9 ball-pocket" would give the answer away.
    const auto result = document_->isResultCurrent() ? document_->wholeResult() : nullptr;
    const std::optional<double> horizon = document_->isWithholding() ? document_->horizon() : std::nullopt;
    loading_ = true;
    questions_->setRowCount(static_cast<int>(questions.size()));
    for (std::size_t i = 0; i < questions.size(); ++i) {
        const PredictQuestion& q = questions[i];
        QString stops = tr("the first collision");
        if (q.event) {
            stops = eventNumber(*q.event);
            if (result && *q.event < static_cast<int>(result->events.size()) && horizon &&
                result->events[std::size_t(*q.event)].time >= *horizon)
                stops = tr("%1 (shown after the reveal)").arg(stops);
            else if (result && *q.event < static_cast<int>(result->events.size()))
                stops = tr("%1 %2 at %3 s")
                            .arg(stops, displayName(result->events[std::size_t(*q.event)].kind))
                            .arg(uiNumber(result->events[std::size_t(*q.event)].time, 3));
            else if (result)
                stops = tr("%1 (not in this shot)").arg(stops);
        }
        QStringList balls;
        for (const std::string& id : q.balls) balls << QString::fromStdString(id);
        const int row = static_cast<int>(i);
        questions_->setItem(row, StopsBeforeColumn, readOnly(stops));
        questions_->setItem(row, BallsColumn, new QTableWidgetItem(balls.join(QStringLiteral(", "))));
        questions_->setItem(row, PromptColumn, new QTableWidgetItem(QString::fromStdString(q.prompt)));
    }
    loading_ = false;
    remove_->setEnabled(questions_->currentRow() >= 0);
}

void PredictPanel::addQuestion()
{
    Setup after = document_->setup();
    PredictQuestion q;
    if (selection_ && selection_->event() >= 0) q.event = selection_->event();
    after.questions.push_back(q);
    document_->edit(tr("Add a lesson question"), after);
}

void PredictPanel::removeQuestion()
{
    const int row = questions_->currentRow();
    Setup after = document_->setup();
    if (row < 0 || row >= static_cast<int>(after.questions.size())) return;
    after.questions.erase(after.questions.begin() + row);
    document_->edit(tr("Remove lesson question %1").arg(row + 1), after);
}

void PredictPanel::commitCell(int row, int column)
{
    if (loading_) return;
    Setup after = document_->setup();
    if (row < 0 || row >= static_cast<int>(after.questions.size())) return;
    PredictQuestion& q = after.questions[static_cast<std::size_t>(row)];
    const QString text = questions_->item(row, column)->text().trimmed();
    if (column == PromptColumn) {
        q.prompt = text.toStdString();
        document_->edit(tr("Edit lesson question %1").arg(row + 1), after);
        return;
    }
    if (column != BallsColumn) return;
    q.balls.clear();
    for (const QString& part : text.split(QLatin1Char(','), Qt::SkipEmptyParts)) {
        const std::string id = part.trimmed().toStdString();
        const auto& balls = after.balls;
        if (std::none_of(balls.begin(), balls.end(), [&id](const Ball& b) { return b.id == id; })) {
            status_->setText(tr("There is no ball \"%1\" in the shot.").arg(part.trimmed()));
            loadQuestions();  // back to what the question holds
            return;
        }
        if (std::find(q.balls.begin(), q.balls.end(), id) == q.balls.end()) q.balls.push_back(id);
    }
    document_->edit(tr("Edit lesson question %1").arg(row + 1), after);
}

void PredictPanel::toggleSession()
{
    if (session_->state() != PredictSession::State::Idle) {
        session_->stop();
        return;
    }
    QString why;
    if (!session_->start(&why)) status_->setText(why);
}

void PredictPanel::refreshMode()
{
    using State = PredictSession::State;
    const State state = session_->state();
    start_->setText(state == State::Idle ? tr("Start") : tr("Stop"));
    reveal_->setEnabled(state == State::Asking);
    add_->setEnabled(state == State::Idle);
    questions_->setEnabled(state == State::Idle);
    const int current = session_->current();
    const int count = static_cast<int>(session_->questions().size());
    QString text;
    switch (state) {
    case State::Idle: break;
    case State::Playing: text = tr("Playing to the first question…"); break;
    case State::Asking: {
        const lesson::AskedQuestion& q = session_->questions()[std::size_t(current)];
        const auto& p = session_->predictions();
        const auto answered = std::count_if(p.begin(), p.end(), [](const lesson::BallPrediction& b) { return b.answered; });
        const QString prompt = PredictionText::prompt(q);
        text = tr("Question %1 of %2: %3\nDrag from each ball where it will go (a click on a ball: it stays). "
                  "%4 of %5 answered.")
                   .arg(current + 1)
                   .arg(count)
                   .arg(prompt)
                   .arg(answered)
                   .arg(p.size());
        break;
    }
    case State::Revealed:
        text = current + 1 < count ? tr("Revealed. Playing on to question %1…").arg(current + 2) : tr("Revealed. Playing on to the end…");
        break;
    case State::Finished:
        text = tr("Done: %1 of %2 questions, mean score %3 %.")
                   .arg(session_->revealed().size())
                   .arg(count)
                   .arg(uiNumber(session_->meanScore() * 100.0, 0));
        break;
    }
    if (state != State::Idle && !session_->skipped().empty())
        text += tr("\nNot asked: %1").arg(QString::fromStdString(session_->skipped().front()));
    status_->setText(text);
}

void PredictPanel::refreshResults()
{
    int rows = 0;
    for (const auto& r : session_->revealed()) rows += static_cast<int>(r.balls.size());
    results_->setRowCount(rows);
    const auto result = session_->questions().empty() ? nullptr : document_->result();
    int row = 0;
    for (const auto& r : session_->revealed()) {
        for (const lesson::BallReveal& b : r.balls) {
            const QString id = result ? QString::fromStdString(result->balls[std::size_t(b.ball)].id) : QString::number(b.ball);
            results_->setItem(row, QuestionColumn, readOnly(QString::number(r.question + 1)));
            results_->setItem(row, BallColumn, readOnly(id));
            results_->setItem(row, GuessColumn, readOnly(b.predicted.answered ? PredictionText::heading(b.predicted.headingDeg) : tr("—")));
            results_->setItem(row, ActualColumn, readOnly(PredictionText::heading(b.actualDeg)));
            results_->setItem(row, ErrorColumn, readOnly(PredictionText::error(b)));
            results_->setItem(row, ScoreColumn, readOnly(PredictionText::score(b.score)));
            ++row;
        }
    }
    refreshMode();
}

}  // namespace cuelab
