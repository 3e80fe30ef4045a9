#include "OddsSection.h"

#include "i18n/DisplayNames.h"

#include "AnalysisJob.h"
#include "OddsMap.h"

#include "editor/Document.h"

#include "Goal.h"
#include "Map.h"
#include "SetupFile.h"
#include "ShotOdds.h"
#include "Tolerance.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <chrono>
#include <cmath>
#include <memory>

namespace cuelab {

using namespace cuelab::analysis;

namespace {

// The presets in the order of the box, then "custom" (the boxes as the user set them).
const char* const kPresetLabels[] = {
    QT_TRANSLATE_NOOP("cuelab::OddsSection", "Computer tournaments (FastFiz)"),
    QT_TRANSLATE_NOOP("cuelab::OddsSection", "Club player"),
    QT_TRANSLATE_NOOP("cuelab::OddsSection", "Professional"),
    QT_TRANSLATE_NOOP("cuelab::OddsSection", "Custom"),
};
const char* const kPresetNames[] = {"fastfiz", "club", "pro"};
constexpr int kCustom = 3;

struct SigmaSpec {
    const char* label;
    const char* tip;
    double maximum;
    int decimals;
};
const SigmaSpec kSigmas[] = {
    {QT_TRANSLATE_NOOP("cuelab::OddsSection", "Heading"),
     QT_TRANSLATE_NOOP("cuelab::OddsSection", "Standard deviation of the aim error, degrees"), 90.0, 3},
    {QT_TRANSLATE_NOOP("cuelab::OddsSection", "Speed"),
     QT_TRANSLATE_NOOP("cuelab::OddsSection", "Standard deviation of the cue speed, m/s"), 5.0, 3},
    {QT_TRANSLATE_NOOP("cuelab::OddsSection", "Side"),
     QT_TRANSLATE_NOOP("cuelab::OddsSection", "Standard deviation of the side tip offset, in ball radii (R)"), 0.5, 4},
    {QT_TRANSLATE_NOOP("cuelab::OddsSection", "Height"),
     QT_TRANSLATE_NOOP("cuelab::OddsSection", "Standard deviation of the height tip offset, in ball radii (R)"), 0.5, 4},
    {QT_TRANSLATE_NOOP("cuelab::OddsSection", "Elevation"),
     QT_TRANSLATE_NOOP("cuelab::OddsSection",
                       "Standard deviation of the cue elevation, degrees (an error below the cloth is read as above it)"),
     45.0, 3},
};

QDoubleSpinBox* numberBox(QWidget* parent, const QString& tip, double low, double high, int decimals)
{
    auto* box = new QDoubleSpinBox(parent);
    box->setRange(low, high);
    box->setDecimals(decimals);
    box->setToolTip(tip);
    // At least as wide as a signed value of three integer digits needs (a heading's 359.9999), not as
    // the range's ends (±1000000.0000): two of the map's ranges then fit side by side in Coach's
    // 234-px column at 800x600 (tst_windowapi); a wider dock widens them.
    box->setMinimumWidth(box->fontMetrics().horizontalAdvance(QStringLiteral("-000.0000")) + 28);
    return box;
}

}  // namespace

OddsSection::OddsSection(Document* document, std::function<QString()> goalText, QWidget* parent)
    : QGroupBox(tr("Odds under execution noise"), parent), document_(document), goalText_(std::move(goalText)),
      job_(new AnalysisJob(this))
{
    preset_ = new QComboBox(this);
    for (const char* label : kPresetLabels) preset_->addItem(tr(label));
    preset_->setToolTip(tr("How the player's strike scatters: normal errors of these standard deviations on every "
                           "strike parameter (FastFiz's model). Computer tournaments: the noise of the computational pool "
                           "tournaments played on FastFiz, a little steadier than a club player and looser than a "
                           "professional; all three are explained in docs/analysis.md"));
    auto* sigmas = new QGridLayout;
    for (StrikeKey k : kStrikeKeys) {
        const auto i = static_cast<std::size_t>(k);
        const SigmaSpec& s = kSigmas[i];
        sigma_[i] = numberBox(this, tr(s.tip), 0.0, s.maximum, s.decimals);
        sigma_[i]->setSuffix(QStringLiteral(" ") + QString::fromUtf8(sigmaUnitOf(k).data()));
        sigma_[i]->setSingleStep(std::pow(10.0, 1 - s.decimals));
        const int row = static_cast<int>(i), column = 0;  // one a row: the section fits a 240-pixel column
        sigmas->addWidget(new QLabel(tr(s.label), this), row, column);
        sigmas->addWidget(sigma_[i], row, column + 1);
        connect(sigma_[i], &QDoubleSpinBox::valueChanged, this, [this] {
            if (!settingPreset_) preset_->setCurrentIndex(kCustom);
        });
    }
    samples_ = new QSpinBox(this);
    samples_->setRange(100, 1000000);
    samples_->setSingleStep(1000);
    samples_->setValue(4000);
    samples_->setToolTip(tr("Strikes of the current shot at most; it stops sooner once the 95% interval is within ±1%"));
    oddsButton_ = new QPushButton(tr("Odds"), this);
    oddsButton_->setToolTip(tr("Strike the current shot again and again with these errors and count how often it "
                               "meets the goal"));
    odds_ = new QLabel(this);
    QFont big = odds_->font();
    big.setPointSizeF(big.pointSizeF() * 1.3);
    big.setBold(true);
    odds_->setFont(big);
    odds_->setToolTip(tr("The share of strikes that meet the goal, and its 95% confidence interval (Wilson)"));

    xKey_ = new QComboBox(this);
    xKey_->setToolTip(tr("The key along the map's horizontal axis"));
    yKey_ = new QComboBox(this);
    yKey_->setToolTip(tr("The key along the map's vertical axis"));
    for (QComboBox* box : {preset_, xKey_, yKey_}) {  // as AnalysisPanel's: never wider than the dock
        box->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
        box->setMinimumContentsLength(12);
    }
    const QString ends[] = {tr("First value of the horizontal axis, in the key's unit"),
                            tr("Last value of the horizontal axis, in the key's unit"),
                            tr("First value of the vertical axis, in the key's unit"),
                            tr("Last value of the vertical axis, in the key's unit")};
    for (std::size_t i = 0; i < range_.size(); ++i) range_[i] = numberBox(this, ends[i], -1e6, 1e6, 4);
    cells_ = new QSpinBox(this);
    cells_->setRange(3, 61);
    cells_->setValue(11);
    cells_->setToolTip(tr("Cells along each axis"));
    cellSamples_ = new QSpinBox(this);
    cellSamples_->setRange(20, 100000);
    cellSamples_->setValue(200);
    cellSamples_->setSingleStep(100);
    cellSamples_->setToolTip(tr("Strikes per cell (every cell uses the same errors, so neighbours compare fairly)"));
    mapButton_ = new QPushButton(tr("Map odds"), this);
    mapButton_->setToolTip(tr("The odds of every cell of the map; the colours stream in"));
    map_ = new OddsMap(this);
    map_->setToolTip(tr("Each cell: how often its shot meets the goal under the noise. The ring marks the best cell, "
                        "the cross the current shot. Click a cell to load its shot (one undo step)."));

    progress_ = new QProgressBar(this);
    progress_->setRange(0, 1);
    progress_->setValue(0);
    cancel_ = new QPushButton(tr("Cancel"), this);
    cancel_->setToolTip(tr("Stop computing odds"));
    cancel_->setEnabled(false);
    status_ = new QLabel(this);
    status_->setWordWrap(true);

    auto* layout = new QVBoxLayout(this);
    auto* presetRow = new QHBoxLayout;
    presetRow->addWidget(new QLabel(tr("Player"), this));
    presetRow->addWidget(preset_, 1);
    layout->addLayout(presetRow);
    layout->addLayout(sigmas);
    auto* oddsRow = new QHBoxLayout;
    oddsRow->addWidget(new QLabel(tr("Strikes"), this));
    oddsRow->addWidget(samples_);
    oddsRow->addStretch(1);
    layout->addLayout(oddsRow);
    layout->addWidget(oddsButton_, 0, Qt::AlignRight);  // under its strikes: the section fits 240 px
    layout->addWidget(odds_);
    auto* form = new QFormLayout;
    form->setRowWrapPolicy(QFormLayout::WrapLongRows);
    // Each key above its range, and the map's button under its cells: the section fits a side
    // column (Coach at 1280x800 keeps the table view wide).
    const auto range = [](QDoubleSpinBox* from, QDoubleSpinBox* to) {
        auto* row = new QHBoxLayout;
        row->setSpacing(4);
        row->addWidget(from, 1);
        row->addWidget(to, 1);
        return row;
    };
    form->addRow(tr("x"), xKey_);
    form->addRow(range(range_[0], range_[1]));  // across the label column too: two values fit a 234-px column
    form->addRow(tr("y"), yKey_);
    form->addRow(range(range_[2], range_[3]));
    form->addRow(tr("Cells"), cells_);
    form->addRow(tr("strikes per cell"), cellSamples_);
    form->addRow(QString(), mapButton_);
    layout->addLayout(form);
    layout->addWidget(map_, 1);
    auto* progressRow = new QHBoxLayout;
    progressRow->addWidget(progress_, 1);
    progressRow->addWidget(cancel_);
    layout->addLayout(progressRow);
    layout->addWidget(status_);

    connect(preset_, &QComboBox::activated, this, &OddsSection::setPreset);
    connect(oddsButton_, &QPushButton::clicked, this, &OddsSection::runOdds);
    connect(mapButton_, &QPushButton::clicked, this, &OddsSection::runMap);
    connect(cancel_, &QPushButton::clicked, this, &OddsSection::cancel);
    connect(map_, &OddsMap::cellClicked, this, [this](int index) { loadCell(index); });
    const auto centreRange = [this](QComboBox* key, QDoubleSpinBox* from, QDoubleSpinBox* to) {
        const Setup& s = document_->setup();
        const auto p = Parameter::resolve(s, key->currentData().toString().toStdString());
        if (!std::holds_alternative<Parameter>(p)) return;
        const double v = std::get<Parameter>(p).number(s);
        from->setValue(v - std::max(0.1, std::abs(v) * 0.1));
        to->setValue(v + std::max(0.1, std::abs(v) * 0.1));
    };
    connect(xKey_, &QComboBox::activated, this, [=, this] { centreRange(xKey_, range_[0], range_[1]); });
    connect(yKey_, &QComboBox::activated, this, [=, this] { centreRange(yKey_, range_[2], range_[3]); });
    connect(job_, &AnalysisJob::progressChanged, this, [this](long long done, long long total) {
        progress_->setRange(0, static_cast<int>(std::min<long long>(total, 1 << 30)));
        progress_->setValue(static_cast<int>(std::min<long long>(done, 1 << 30)));
    });
    connect(job_, &AnalysisJob::runningChanged, this, [this](bool running) { cancel_->setEnabled(running); });
    connect(job_, &AnalysisJob::finished, this, [this](bool cancelled) {
        if (!cancelled) return;
        setStatus(tr("Cancelled."));
        if (!current_) odds_->clear();  // not "striking…" any more
    });
    connect(document_, &Document::setupChanged, this, &OddsSection::onSetupChanged);
    connect(document_, &Document::documentReplaced, this, [this] {
        map_->clear();
        mapBase_.reset();
    });
    setPreset(0);
    updateKeys();
}

OddsSection::~OddsSection() = default;

QString OddsSection::oddsText() const { return odds_->text(); }
QString OddsSection::statusText() const { return status_->text(); }
void OddsSection::setStatus(const QString& text) { status_->setText(text); }

QDoubleSpinBox* OddsSection::rangeBox(int axis, int end) const
{
    return range_[static_cast<std::size_t>(std::clamp(axis, 0, 1) * 2 + std::clamp(end, 0, 1))];
}

double OddsSection::struckBallRadius() const
{
    const Setup& s = document_->setup();
    if (s.shot)
        for (const Ball& b : s.balls)
            if (b.id == s.shot->ball) return b.radius;
    return Ball{}.radius;
}

void OddsSection::setPreset(int index)
{
    preset_->setCurrentIndex(index);
    if (index < 0 || index >= kCustom) return;
    const auto model = presetNoise(kPresetNames[index], struckBallRadius());
    if (!model) return;
    settingPreset_ = true;
    for (StrikeKey k : kStrikeKeys) sigma_[static_cast<std::size_t>(k)]->setValue((*model)[k]);
    settingPreset_ = false;
}

NoiseModel OddsSection::noise() const
{
    // A preset's own numbers, not the boxes' rounding of them: the window's "fastfiz" is the CLI's.
    if (preset_->currentIndex() >= 0 && preset_->currentIndex() < kCustom)
        if (const auto model = presetNoise(kPresetNames[preset_->currentIndex()], struckBallRadius())) return *model;
    NoiseModel m;
    for (StrikeKey k : kStrikeKeys) m[k] = sigma_[static_cast<std::size_t>(k)]->value();
    return m;
}

void OddsSection::updateKeys()
{
    const Setup& s = document_->setup();
    // Each box names its keys in words with their units (the key itself is the item's data).
    const QString x = xKey_->currentData().toString(), y = yKey_->currentData().toString();
    // The boxes are filled again only when the keys change (a ball added, renamed, removed): not at
    // every step of a drag.
    std::vector<std::string> keys = overridableKeys(s, true);
    const bool sameKeys = keys == keyChoices_;
    if (!sameKeys) {
        keyChoices_ = std::move(keys);
        xKey_->clear();
        yKey_->clear();
    }
    for (const std::string& key : sameKeys ? std::vector<std::string>() : keyChoices_) {
        xKey_->addItem(displayKeyName(key), QString::fromStdString(key));
        yKey_->addItem(displayKeyName(key), QString::fromStdString(key));
    }
    const auto choose = [](QComboBox* box, const QString& wanted, const QString& fallback) {
        const int i = box->findData(wanted.isEmpty() ? fallback : wanted);
        box->setCurrentIndex(i >= 0 ? i : 0);
    };
    choose(xKey_, x, QStringLiteral("shot.heading"));
    choose(yKey_, y, QStringLiteral("shot.side"));
    if (x.isEmpty() && s.shot) {
        range_[0]->setValue(s.shot->headingDeg - 1.0);
        range_[1]->setValue(s.shot->headingDeg + 1.0);
        range_[2]->setValue(-0.4);
        range_[3]->setValue(0.4);
    }
    const bool hasShot = s.shot.has_value();
    oddsButton_->setEnabled(hasShot);
    mapButton_->setEnabled(hasShot);
}

std::optional<SweepSpec> OddsSection::baseSpec(const Setup& setup)
{
    if (!setup.shot) {
        setStatus(tr("The setup has no cue strike: nothing to scatter."));
        return std::nullopt;
    }
    auto parsed = parseGoal(goalText_().trimmed().toStdString());
    if (auto* error = std::get_if<std::string>(&parsed)) {
        setStatus(tr("Goal: %1").arg(QString::fromStdString(*error)));
        return std::nullopt;
    }
    const Goal& goal = std::get<Goal>(parsed);
    std::string error;
    auto resolved = ResolvedGoal::resolve(goal, setup, &error);
    if (!resolved) {
        setStatus(tr("Goal: %1").arg(QString::fromStdString(error)));
        return std::nullopt;
    }
    goalIsPot_ = false;
    for (const GoalTerm& t : goal.terms)
        if (t.kind == GoalTerm::Kind::Pocketed && !t.negated) goalIsPot_ = true;
    SweepSpec spec;
    spec.base = setup;
    spec.goal = std::move(*resolved);
    spec.setupName = document_->displayName().toStdString();
    return spec;
}

void OddsSection::runOdds()
{
    const auto spec = baseSpec(document_->setup());
    if (!spec) return;
    OddsRequest request;
    request.noise = noise();
    request.samples = samples_->value();
    request.halfWidth = 0.01;
    current_.reset();
    odds_->setText(tr("striking…"));
    setStatus(tr("Striking the shot up to %1 times.").arg(request.samples));
    job_->start([spec = *spec, request, this](AnalysisJob::Context& context) {
        const OddsResult r = shotOdds(spec, {}, request, 0, context.stop, context.progress);
        context.progress(r.samples, r.samples);
        if (context.stop.stop_requested()) return;
        context.post([this, r] {
            current_ = r;
            const Interval ci = r.ci95();
            const QString form = goalIsPot_ ? tr("goes in %1 % (%2–%3 %)") : tr("meets the goal %1 % (%2–%3 %)");
            odds_->setText(form.arg(std::lround(r.probability() * 100.0))
                               .arg(std::lround(ci.low * 100.0))
                               .arg(std::lround(ci.high * 100.0)));
            QString detail = tr("%1 of %2 strikes met the goal").arg(r.successes).arg(r.samples);
            if (r.miscues > 0) detail += tr("; %1 miscues (tip beyond 0.5 R)").arg(r.miscues);
            if (r.stoppedEarly) detail += tr("; stopped once the interval was within ±1%");
            setStatus(detail + QLatin1Char('.'));
        });
    });
}

void OddsSection::runMap()
{
    const auto base = baseSpec(document_->setup());
    if (!base) return;
    const auto x = Parameter::resolve(base->base, xKey_->currentData().toString().toStdString());
    const auto y = Parameter::resolve(base->base, yKey_->currentData().toString().toStdString());
    if (!std::holds_alternative<Parameter>(x) || !std::holds_alternative<Parameter>(y))
        return setStatus(tr("Choose two keys of this setup."));
    if (xKey_->currentData() == yKey_->currentData()) return setStatus(tr("Choose two different keys."));
    const int n = cells_->value();
    SweepSpec spec = mapSpec(*base, Variation{std::get<Parameter>(x), Range{range_[0]->value(), range_[1]->value(), n}},
                             Variation{std::get<Parameter>(y), Range{range_[2]->value(), range_[3]->value(), n}});
    OddsRequest request;
    request.noise = noise();
    request.samples = cellSamples_->value();
    spec.odds = request;
    mapY_ = spec.variations[0];
    mapX_ = spec.variations[1];
    mapBase_ = base->base;
    map_->reset(*mapX_, *mapY_);
    map_->setCurrent(mapX_->parameter.number(base->base), mapY_->parameter.number(base->base));
    setStatus(tr("Mapping the odds of %1 shots, %2 strikes each.").arg(static_cast<long long>(n) * n).arg(request.samples));
    OddsMap* map = map_;
    job_->start([spec, map, this](AnalysisJob::Context& context) {
        const long long total = shotCount(spec);
        using Cells = std::vector<std::pair<long long, std::optional<OddsResult>>>;
        auto batch = std::make_shared<Cells>();
        long long done = 0;
        auto last = std::chrono::steady_clock::now();
        const auto flush = [&] {
            if (batch->empty()) return;
            context.post([map, batch] {
                for (const auto& [index, odds] : *batch) map->setCell(index, odds);
            });
            batch = std::make_shared<Cells>();
        };
        runSweep(
            spec,
            [&](ShotResult& shot) {
                batch->emplace_back(shot.index, shot.odds);
                ++done;
                const auto now = std::chrono::steady_clock::now();
                if (now - last > std::chrono::milliseconds(40)) {
                    last = now;
                    flush();
                    context.progress(done, total);
                }
            },
            context.stop);
        flush();
        context.progress(done, total);
        if (!context.stop.stop_requested())
            context.post([this, map] {
                setStatus(map->bestCell() >= 0 ? tr("Best cell (ringed): %1. Click a cell to load its shot.")
                                                     .arg(map->readout(map->bestCell()))
                                               : tr("No cell of the map is a legal shot."));
            });
    });
}

void OddsSection::cancel() { job_->cancel(); }

bool OddsSection::isMapCellOf(const Setup& setup) const
{
    if (!mapBase_ || !mapX_ || !mapY_) return false;
    if (setup.balls.size() != mapBase_->balls.size() || setup.shot.has_value() != mapBase_->shot.has_value())
        return false;
    Setup candidate = *mapBase_;
    mapX_->parameter.setNumber(candidate, mapX_->parameter.number(setup));
    mapY_->parameter.setNumber(candidate, mapY_->parameter.number(setup));
    return io::serializeSetup(candidate) == io::serializeSetup(setup);
}

bool OddsSection::loadCell(int index)
{
    if (!mapBase_ || !mapX_ || !mapY_ || index < 0 || index >= map_->columns() * map_->rows()) return false;
    Setup setup = document_->setup();
    if (!isMapCellOf(setup)) {
        setStatus(tr("The setup changed since the map was made; map again."));
        return false;
    }
    const std::vector<double> v = map_->valuesOf(index);
    mapX_->parameter.setNumber(setup, v[0]);
    mapY_->parameter.setNumber(setup, v[1]);
    const QString text = tr("Load shot from the odds map (%1 = %2, %3 = %4)")
                             .arg(QString::fromStdString(mapX_->parameter.key())).arg(v[0], 0, 'g', 6)
                             .arg(QString::fromStdString(mapY_->parameter.key())).arg(v[1], 0, 'g', 6);
    const bool ok = document_->edit(text, setup);
    document_->endMerge();
    setStatus(ok ? text : tr("That cell's shot is not a legal setup."));
    return ok;
}

void OddsSection::onSetupChanged()
{
    const Setup& setup = document_->setup();
    if (job_->isRunning()) job_->cancel();
    if (current_ || !odds_->text().isEmpty()) {
        current_.reset();
        odds_->setText(tr("the shot changed: press Odds"));
    }
    if (isMapCellOf(setup)) {
        map_->setCurrent(mapX_->parameter.number(setup), mapY_->parameter.number(setup));
    } else if (!map_->isEmpty()) {
        map_->clear();
        mapBase_.reset();
        setStatus(tr("The setup changed: the map of odds was dropped."));
    }
    // A preset's tip offsets are in radii of the struck ball, which may have changed.
    if (preset_->currentIndex() < kCustom) setPreset(preset_->currentIndex());
    updateKeys();
}

}  // namespace cuelab
