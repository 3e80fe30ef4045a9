#include "GameControl.h"

#include "Document.h"

#include <QComboBox>
#include <algorithm>
#include <QHBoxLayout>
#include <QSignalBlocker>

namespace cuelab {

GameControl::GameControl(Document* document, QWidget* parent) : QWidget(parent), document_(document)
{
    rules_ = new QComboBox(this);
    rules_->setObjectName(QStringLiteral("gameRules"));
    rules_->setToolTip(tr("The game whose rules judge the shot: the Outcome dock then says whether it is legal or a foul, "
                          "and why (docs/rules.md)"));
    rules_->addItem(tr("No rules"), QString());
    for (GameRules r : {GameRules::EightBall, GameRules::NineBall, GameRules::TenBall, GameRules::Snooker, GameRules::ThreeCushion}) {
        const QString name = QString::fromUtf8(toString(r).data(), static_cast<qsizetype>(toString(r).size()));
        rules_->addItem(r == GameRules::Snooker ? tr("Snooker") : r == GameRules::ThreeCushion ? tr("Three-cushion") : name, name);
    }
    state_ = new QComboBox(this);
    state_->setObjectName(QStringLiteral("gameState"));
    auto* layout = new QHBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(rules_, 1);
    layout->addWidget(state_, 1);
    connect(rules_, &QComboBox::activated, this, &GameControl::commitRules);
    connect(state_, &QComboBox::activated, this, &GameControl::commitState);
    connect(document_, &Document::setupChanged, this, &GameControl::refresh);
    refresh();
}

void GameControl::refresh()
{
    refreshing_ = true;
    const std::optional<GameSpec>& game = document_->setup().game;
    const QSignalBlocker a(rules_), b(state_);
    const QString rules = game ? QString::fromUtf8(toString(game->rules).data(), static_cast<qsizetype>(toString(game->rules).size()))
                               : QString();
    rules_->setCurrentIndex(std::max(0, rules_->findData(rules)));
    state_->clear();
    if (game && game->rules == GameRules::EightBall) {
        state_->setToolTip(tr("The striker's group: open table, solids (1-7) or stripes (9-15)"));
        state_->addItem(tr("Open table"), QStringLiteral("open"));
        state_->addItem(tr("Solids"), QStringLiteral("solids"));
        state_->addItem(tr("Stripes"), QStringLiteral("stripes"));
        const std::string_view group = toString(game->group.value_or(PoolGroup::Open));
        state_->setCurrentIndex(std::max(0, state_->findData(QString::fromUtf8(group.data(), static_cast<qsizetype>(group.size())))));
    } else if (game && game->rules == GameRules::Snooker) {
        state_->setToolTip(tr("The ball on: a red, any colour (after a red), or a named colour"));
        state_->addItem(tr("Red on"), QStringLiteral("red"));
        state_->addItem(tr("Colour on"), QStringLiteral("colour"));
        state_->addItem(tr("Yellow on"), QStringLiteral("yellow"));
        state_->addItem(tr("Green on"), QStringLiteral("green"));
        state_->addItem(tr("Brown on"), QStringLiteral("brown"));
        state_->addItem(tr("Blue on"), QStringLiteral("blue"));
        state_->addItem(tr("Pink on"), QStringLiteral("pink"));
        state_->addItem(tr("Black on"), QStringLiteral("black"));
        const std::string_view on = toString(game->on.value_or(SnookerOn::Red));
        state_->setCurrentIndex(std::max(0, state_->findData(QString::fromUtf8(on.data(), static_cast<qsizetype>(on.size())))));
    }
    state_->setVisible(state_->count() > 0);
    refreshing_ = false;
}

void GameControl::commitRules()
{
    if (refreshing_) return;
    Setup after = document_->setup();
    const std::string name = rules_->currentData().toString().toStdString();
    GameRules rules{};
    if (name.empty()) {
        if (!after.game) return;
        after.game.reset();
    } else {
        if (!parseGameRules(name, rules) || (after.game && after.game->rules == rules)) return;
        after.game = GameSpec{rules, {}, {}, {}, false};
    }
    const QString text = after.game ? tr("Judge the shot by the rules of %1").arg(rules_->currentText()) : tr("Judge the shot by no rules");
    if (!document_->edit(text, after)) refresh();
}

void GameControl::commitState()
{
    if (refreshing_ || !document_->setup().game) return;
    Setup after = document_->setup();
    const std::string value = state_->currentData().toString().toStdString();
    QString text;
    if (after.game->rules == GameRules::EightBall) {
        PoolGroup group{};
        if (!parsePoolGroup(value, group)) return;
        after.game->group = group;
        text = tr("Set the striker's group to %1").arg(state_->currentText());
    } else {
        SnookerOn on{};
        if (!parseSnookerOn(value, on)) return;
        after.game->on = on;
        text = tr("Set the ball on: %1").arg(state_->currentText());
    }
    if (!document_->edit(text, after)) refresh();
}

}  // namespace cuelab
