// The shot diagram and the lesson report (widgets/export): the SVG parses and holds one circle per
// ball on the table, at its final position; the PDFs have the pages they should; a file that cannot
// be written says so, and a cancelled report leaves the file that was there.

#include "SetupFile.h"
#include "Simulation.h"
#include "export/DiagramFiles.h"
#include "export/LessonReport.h"
#include "export/ShotDiagram.h"
#include "ExampleSetup.h"

#include <QFile>
#include <QRegularExpression>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include <cmath>
#include <memory>

using namespace cuelab;

namespace {

struct Loaded {
    std::shared_ptr<const SimulationResult> result;
    DiagramText text;
};

Loaded load(const QString& file)
{
    const Setup setup = loadExample(file);
    return {std::make_shared<const SimulationResult>(simulate(setup)),
            {QString::fromStdString(setup.name), QString::fromStdString(setup.notes)}};
}

struct Circle {
    double cx, cy, r;
};

// Every <circle> of an SVG, mapped through the matrix() transforms of its enclosing groups.
std::vector<Circle> circlesOf(const QByteArray& svg, QString* problem)
{
    std::vector<Circle> out;
    std::vector<QTransform> stack{QTransform()};
    QXmlStreamReader xml(svg);
    static const QRegularExpression matrix(QStringLiteral("matrix\\(([^)]*)\\)"));
    while (!xml.atEnd()) {
        const QXmlStreamReader::TokenType token = xml.readNext();
        if (token == QXmlStreamReader::StartElement) {
            QTransform m = stack.back();
            const QString transform = xml.attributes().value(QStringLiteral("transform")).toString();
            const QRegularExpressionMatch match = matrix.match(transform);
            if (match.hasMatch()) {
                const QStringList v = match.captured(1).split(QRegularExpression(QStringLiteral("[ ,]+")), Qt::SkipEmptyParts);
                if (v.size() == 6)
                    m = QTransform(v[0].toDouble(), v[1].toDouble(), v[2].toDouble(), v[3].toDouble(), v[4].toDouble(),
                                   v[5].toDouble()) * m;
            }
            stack.push_back(m);
            if (xml.name() == QLatin1String("circle")) {
                const QPointF c = m.map(QPointF(xml.attributes().value(QStringLiteral("cx")).toDouble(),
                                                xml.attributes().value(QStringLiteral("cy")).toDouble()));
                out.push_back({c.x(), c.y(), xml.attributes().value(QStringLiteral("r")).toDouble() * std::sqrt(std::abs(m.determinant()))});
            }
        } else if (token == QXmlStreamReader::EndElement) {
            stack.pop_back();
        }
    }
    if (xml.hasError()) *problem = xml.errorString();
    return out;
}

int pdfPages(const QString& path)
{
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return -1;
    const QByteArray bytes = f.readAll();
    // Page objects: "/Type /Page" not followed by "s" (the page tree is "/Type /Pages").
    static const QRegularExpression page(QStringLiteral("/Type\\s*/Page(?!s)"));
    return static_cast<int>(QString::fromLatin1(bytes).count(page));
}

QByteArray readAll(const QString& path)
{
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

}  // namespace

class TestDiagram : public QObject {
    Q_OBJECT

private slots:
    void svgCirclesAreTheBallsAtRest_data();
    void svgCirclesAreTheBallsAtRest();
    void svgAtATime();
    void pdfDiagramIsOnePage();
    void reportPages_data();
    void reportPages();
    void unwritablePlaceSaysSo();
    void cancelledReportKeepsTheOldFile();
    void pngOfAChosenSize();

private:
    QTemporaryDir dir_;
};

void TestDiagram::svgCirclesAreTheBallsAtRest_data()
{
    QTest::addColumn<QString>("file");
    for (const char* f : {"half-ball-cut.json", "two-rail-kick.json", "9-ball-break.json", "snooker-plant.json", "three-cushion.json"})
        QTest::newRow(f) << QString::fromLatin1(f);
}

void TestDiagram::svgCirclesAreTheBallsAtRest()
{
    QFETCH(QString, file);
    const Loaded l = load(file);
    const ShotDiagram diagram(l.result, l.text);
    const QString path = dir_.filePath(file + QStringLiteral(".svg"));
    QString error;
    QVERIFY2(writeDiagramSvg(diagram, path, &error), qPrintable(error));
    const QByteArray svg = readAll(path);
    QVERIFY(QSvgRenderer(svg).isValid());
    QString problem;
    const std::vector<Circle> circles = circlesOf(svg, &problem);
    QVERIFY2(problem.isEmpty(), qPrintable(problem));

    const SimulationResult& r = *l.result;
    const QTransform m = diagram.tableToCanvas();
    int onTable = 0;
    for (int b = 0; b < static_cast<int>(r.balls.size()); ++b) {
        const BallState s = r.stateAt(b, r.endTime);
        if (s.motion == MotionState::Pocketed) continue;
        ++onTable;
        const QPointF expected = m.map(QPointF(s.position.x(), s.position.y()));
        const double radius = r.balls[b].radius * m.m11();
        int found = 0;
        for (const Circle& c : circles)
            if (std::hypot(c.cx - expected.x(), c.cy - expected.y()) < 0.05 && std::abs(c.r - radius) < 0.05) ++found;
        QVERIFY2(found == 1, qPrintable(QStringLiteral("ball %1: %2 circles at its final position").arg(QString::fromStdString(r.balls[b].id)).arg(found)));
    }
    QCOMPARE(static_cast<int>(circles.size()), onTable);
    // The caption holds the outcome and the lesson's title.
    QVERIFY(svg.contains("Outcome:"));
    QVERIFY(svg.contains(l.text.title.toHtmlEscaped().toUtf8()));
}

void TestDiagram::svgAtATime()
{
    // At t = 0 every ball is drawn at its start.
    const Loaded l = load(QStringLiteral("half-ball-cut.json"));
    const ShotDiagram diagram(l.result, l.text, 0.0);
    const QString path = dir_.filePath(QStringLiteral("start.svg"));
    QString error;
    QVERIFY(writeDiagramSvg(diagram, path, &error));
    QString problem;
    const std::vector<Circle> circles = circlesOf(readAll(path), &problem);
    QCOMPARE(circles.size(), l.result->balls.size());
    const QPointF cue = diagram.tableToCanvas().map(QPointF(l.result->balls[0].state.position.x(), l.result->balls[0].state.position.y()));
    QVERIFY(std::hypot(circles[0].cx - cue.x(), circles[0].cy - cue.y()) < 0.05);
}

void TestDiagram::pdfDiagramIsOnePage()
{
    const Loaded l = load(QStringLiteral("two-rail-kick.json"));
    const QString path = dir_.filePath(QStringLiteral("kick.pdf"));
    QString error;
    QVERIFY2(writeDiagram(ShotDiagram(l.result, l.text), path, &error), qPrintable(error));
    QVERIFY(readAll(path).startsWith("%PDF-"));
    QCOMPARE(pdfPages(path), 1);
}

void TestDiagram::reportPages_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<int>("pages");
    // diagram, notes and outcome, the key collision, events (40 a page), plots
    QTest::newRow("half-ball cut") << "half-ball-cut.json" << 5;
    QTest::newRow("8-ball break") << "8-ball-break.json" << -1;  // computed below from the events
}

void TestDiagram::reportPages()
{
    QFETCH(QString, file);
    QFETCH(int, pages);
    const Loaded l = load(file);
    const LessonReport report(l.result, l.text.title, l.text.notes);
    const int events = static_cast<int>(l.result->events.size());
    const int expected = pages > 0 ? pages : 4 + (events + LessonReport::kEventRowsPerPage - 1) / LessonReport::kEventRowsPerPage;
    QCOMPARE(report.pageCount(), expected);
    if (pages < 0) QVERIFY(expected >= 5);  // the break's table runs over several pages
    const QString path = dir_.filePath(file + QStringLiteral(".pdf"));
    QString error;
    int calls = 0;
    QVERIFY2(report.write(path, &error, [&](int done, int total) {
        ++calls;
        return done <= total;
    }), qPrintable(error));
    QCOMPARE(calls, expected);
    QCOMPARE(pdfPages(path), expected);
}

void TestDiagram::unwritablePlaceSaysSo()
{
    const Loaded l = load(QStringLiteral("half-ball-cut.json"));
    const ShotDiagram diagram(l.result, l.text);
    for (const QString& path : {QStringLiteral("/proc/cuelab-diagram.svg"), dir_.filePath(QStringLiteral("no/such/dir/d.pdf"))}) {
        QString error;
        QVERIFY(!writeDiagram(diagram, path, &error));
        QVERIFY2(error.startsWith(path), qPrintable(error));
        QVERIFY(!QFile::exists(path));
    }
    QString error;
    QVERIFY(!LessonReport(l.result, l.text.title, l.text.notes).write(QStringLiteral("/proc/report.pdf"), &error));
    QVERIFY2(error.contains(QLatin1String("cannot write")), qPrintable(error));
    QVERIFY(!writeDiagram(diagram, dir_.filePath(QStringLiteral("d.gif")), &error));
    QVERIFY2(error.contains(QLatin1String(".svg, .pdf or .png")), qPrintable(error));
}

void TestDiagram::cancelledReportKeepsTheOldFile()
{
    const Loaded l = load(QStringLiteral("8-ball-break.json"));
    const QString path = dir_.filePath(QStringLiteral("old.pdf"));
    QVERIFY(writeFileAtomically(path, "the old file", nullptr));
    QString error;
    // Cancel after the second page.
    QVERIFY(!LessonReport(l.result, l.text.title, l.text.notes).write(path, &error, [](int done, int) { return done < 2; }));
    QCOMPARE(error, QStringLiteral("cancelled"));
    QCOMPARE(readAll(path), QByteArray("the old file"));
    QCOMPARE(QDir(dir_.path()).entryList(QDir::Files).filter(QStringLiteral("old")).size(), 1);  // no temporary left
}

void TestDiagram::pngOfAChosenSize()
{
    const Loaded l = load(QStringLiteral("stun-cut.json"));
    const QString path = dir_.filePath(QStringLiteral("d.png"));
    QString error;
    const ShotDiagram diagram(l.result, l.text, -1.0, {true});
    QVERIFY(writeDiagramPng(diagram, path, QSize(800, 600), &error));
    const QImage image(path);
    QCOMPARE(image.size(), QSize(800, 600));
    // Cloth style: an empty spot of the table (near the top-left corner) is green.
    const double scale = std::min(800.0 / ShotDiagram::kCanvasWidth, 600.0 / diagram.canvasHeight());
    const QPointF canvas = diagram.tableToCanvas().map(QPointF(0.25, 1.05));
    const QPoint pixel(qRound((800 - scale * ShotDiagram::kCanvasWidth) / 2 + scale * canvas.x()),
                       qRound((600 - scale * diagram.canvasHeight()) / 2 + scale * canvas.y()));
    const QColor middle = image.pixelColor(pixel);
    QVERIFY2(middle.green() > middle.red() + 40, qPrintable(middle.name()));
}

QTEST_MAIN(TestDiagram)
#include "tst_diagram.moc"
