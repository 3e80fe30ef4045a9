// parseRecording: JSON or CSV text -> Recording, refusing anything the contract does not allow.
// The shape (keys, types, CSV columns) is checked here; the values (times, table, sample counts) by
// core/recording's recordingProblem, whose messages are only formatted here. The table object is
// read by the setup loader itself, so that it accepts and refuses exactly what a setup's does.

#include "JsonDuplicateKeys.h"
#include "JsonText.h"
#include "RecordingFile.h"
#include "SetupFile.h"

#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QList>

#include <cmath>
#include <map>

namespace cuelab::io {

namespace {

struct Refusal {
    QString path;
    QString message;
};

[[noreturn]] void refuse(const QString& path, const QString& message) { throw Refusal{path, message}; }

QString child(const QString& path, const QString& key) { return path.isEmpty() ? key : path + QLatin1Char('.') + key; }

void onlyKeys(const QJsonObject& object, const QString& path, const QStringList& allowed)
{
    for (auto it = object.begin(); it != object.end(); ++it)
        if (!allowed.contains(it.key()))
            refuse(child(path, it.key()),
                   QStringLiteral("unknown key (expected one of: %1)").arg(allowed.join(QStringLiteral(", "))));
}

double number(const QJsonValue& v, const QString& path)
{
    if (!v.isDouble()) refuse(path, QStringLiteral("expected a number"));
    const double x = v.toDouble();
    if (!std::isfinite(x)) refuse(path, QStringLiteral("the number is not finite"));
    return x;
}

QString text(const QJsonObject& object, const QString& key, const QString& path, bool required)
{
    if (!object.contains(key)) {
        if (required) refuse(child(path, key), QStringLiteral("required key is missing"));
        return {};
    }
    const QJsonValue v = object.value(key);
    if (!v.isString()) refuse(child(path, key), QStringLiteral("expected a string"));
    return v.toString();
}

// The table object through the setup loader: a setup with this table and no balls.
TableSpec parseTable(const QJsonValue& table)
{
    QJsonObject setup;
    setup.insert(QStringLiteral("format"), QStringLiteral("cuelab-setup"));
    setup.insert(QStringLiteral("version"), 1);
    setup.insert(QStringLiteral("table"), table);
    setup.insert(QStringLiteral("balls"), QJsonArray());
    QString error;
    const std::optional<Setup> parsed = parseSetup(QJsonDocument(setup).toJson(), QString(), &error);
    // The loader's message is ": table.kind: unknown ..." (an empty file name): its path and problem.
    if (!parsed) {
        const QString rest = error.mid(2);
        const qsizetype colon = rest.indexOf(QStringLiteral(": "));
        refuse(colon > 0 ? rest.left(colon) : QStringLiteral("table"), colon > 0 ? rest.mid(colon + 2) : rest);
    }
    return parsed->table;
}

Recording parseJson(const QJsonDocument& document)
{
    if (!document.isObject()) refuse(QString(), QStringLiteral("expected a JSON object at the top level"));
    const QJsonObject root = document.object();
    if (!root.contains(QStringLiteral("format")))
        refuse(QStringLiteral("format"), QStringLiteral("required key is missing (not a CueLab recording?)"));
    const QString format = text(root, QStringLiteral("format"), QString(), true);
    if (format != QLatin1String("cuelab-recording"))
        refuse(QStringLiteral("format"), QStringLiteral("expected \"cuelab-recording\", found \"%1\"").arg(format));
    if (!root.contains(QStringLiteral("version"))) refuse(QStringLiteral("version"), QStringLiteral("required key is missing"));
    const double version = number(root.value(QStringLiteral("version")), QStringLiteral("version"));
    if (version != 1.0)
        refuse(QStringLiteral("version"),
               QStringLiteral("version %1 is not supported (this CueLab reads version 1)").arg(version));
    onlyKeys(root, QString(),
             {QStringLiteral("format"), QStringLiteral("version"), QStringLiteral("name"), QStringLiteral("source"),
              QStringLiteral("table"), QStringLiteral("balls")});
    Recording rec;
    rec.name = text(root, QStringLiteral("name"), QString(), false).toStdString();
    rec.source = text(root, QStringLiteral("source"), QString(), false).toStdString();
    if (root.contains(QStringLiteral("table"))) rec.table = parseTable(root.value(QStringLiteral("table")));
    if (!root.contains(QStringLiteral("balls"))) refuse(QStringLiteral("balls"), QStringLiteral("required key is missing"));
    const QJsonValue balls = root.value(QStringLiteral("balls"));
    if (!balls.isArray()) refuse(QStringLiteral("balls"), QStringLiteral("expected an array"));
    const QJsonArray array = balls.toArray();
    for (qsizetype i = 0; i < array.size(); ++i) {
        const QString path = QStringLiteral("balls[%1]").arg(i);
        if (!array[i].isObject()) refuse(path, QStringLiteral("expected an object"));
        const QJsonObject o = array[i].toObject();
        onlyKeys(o, path, {QStringLiteral("id"), QStringLiteral("radius"), QStringLiteral("samples")});
        RecordedBall ball;
        ball.id = text(o, QStringLiteral("id"), path, true).toStdString();
        if (o.contains(QStringLiteral("radius")))
            ball.radius = number(o.value(QStringLiteral("radius")), child(path, QStringLiteral("radius")));
        const QString samplesPath = child(path, QStringLiteral("samples"));
        if (!o.contains(QStringLiteral("samples"))) refuse(samplesPath, QStringLiteral("required key is missing"));
        const QJsonValue samples = o.value(QStringLiteral("samples"));
        if (!samples.isArray()) refuse(samplesPath, QStringLiteral("expected an array of [t, x, y]"));
        const QJsonArray list = samples.toArray();
        ball.samples.reserve(static_cast<std::size_t>(list.size()));
        for (qsizetype k = 0; k < list.size(); ++k) {
            const QString at = samplesPath + QStringLiteral("[%1]").arg(k);
            if (!list[k].isArray() || list[k].toArray().size() != 3)
                refuse(at, QStringLiteral("expected [t, x, y] (seconds, metres, metres)"));
            const QJsonArray s = list[k].toArray();
            ball.samples.push_back({number(s[0], at + QStringLiteral("[0]")),
                                    Vec2(number(s[1], at + QStringLiteral("[1]")), number(s[2], at + QStringLiteral("[2]")))});
        }
        rec.balls.push_back(std::move(ball));
    }
    return rec;
}

bool isCsv(const QByteArray& text) { return text.trimmed().startsWith("t,ball,x,y"); }

double csvNumber(const QByteArray& field, const QString& where, const char* column)
{
    bool ok = false;
    const double x = field.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(x))
        refuse(where, QStringLiteral("%1: expected a number, found \"%2\"")
                          .arg(QLatin1String(column), QString::fromUtf8(field.trimmed())));
    return x;
}

// CSV rows may interleave the balls; each ball's samples keep the order of their rows. Balls are
// listed in the order they first appear. A problem of the values is reported at its row.
Recording parseCsv(const QByteArray& text, const TableSpec& table, std::map<QString, int>& rowOfSample)
{
    Recording rec;
    rec.table = table;
    const QList<QByteArray> lines = text.split('\n');
    bool header = true;
    for (qsizetype n = 0; n < lines.size(); ++n) {
        QByteArray line = lines[n];
        if (line.endsWith('\r')) line.chop(1);
        const QString where = QStringLiteral("line %1").arg(n + 1);
        if (header) {
            if (line.trimmed() != "t,ball,x,y") refuse(where, QStringLiteral("expected the header t,ball,x,y"));
            header = false;
            continue;
        }
        if (line.trimmed().isEmpty()) continue;
        const QList<QByteArray> fields = line.split(',');
        if (fields.size() != 4)
            refuse(where, QStringLiteral("expected 4 fields (t,ball,x,y), found %1").arg(fields.size()));
        const std::string id = fields[1].trimmed().toStdString();
        if (id.empty()) refuse(where, QStringLiteral("ball: the id is empty"));
        const RecordedSample s{csvNumber(fields[0], where, "t"),
                               Vec2(csvNumber(fields[2], where, "x"), csvNumber(fields[3], where, "y"))};
        std::size_t index = 0;
        while (index < rec.balls.size() && rec.balls[index].id != id) ++index;
        if (index == rec.balls.size()) rec.balls.push_back(RecordedBall{id, std::nullopt, {}});
        rec.balls[index].samples.push_back(s);
        rowOfSample[QStringLiteral("balls[%1].samples[%2]").arg(index).arg(rec.balls[index].samples.size() - 1)] =
            static_cast<int>(n + 1);
    }
    if (header) refuse(QStringLiteral("line 1"), QStringLiteral("expected the header t,ball,x,y"));
    return rec;
}

// A CSV has no JSON paths: a sample's problem is at its line, any other at its ball ("ball \"1\"").
QString csvPlace(const QString& path, const Recording& rec, const std::map<QString, int>& rowOfSample)
{
    const auto row = rowOfSample.find(path);
    if (row != rowOfSample.end()) return QStringLiteral("line %1").arg(row->second);
    const qsizetype open = path.indexOf(QLatin1Char('[')), close = path.indexOf(QLatin1Char(']'));
    if (!path.startsWith(QLatin1String("balls[")) || close < open) return path;
    const auto index = static_cast<std::size_t>(path.mid(open + 1, close - open - 1).toInt());
    return index < rec.balls.size() ? QStringLiteral("ball \"%1\"").arg(QString::fromStdString(rec.balls[index].id)) : path;
}

std::pair<int, int> lineAndColumn(const QByteArray& text, qsizetype offset)
{
    int line = 1, column = 1;
    for (qsizetype i = 0; i < std::min(offset, text.size()); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
            ++column;
        }
    }
    return {line, column};
}

}  // namespace

std::optional<Recording> parseRecording(const QByteArray& text, const QString& fileName, QString* error,
                                        const TableSpec& csvTable)
{
    const auto fail = [&](const QString& path, const QString& message) -> std::optional<Recording> {
        if (error)
            *error = path.isEmpty() ? QStringLiteral("%1: %2").arg(fileName, message)
                                    : QStringLiteral("%1: %2: %3").arg(fileName, path, message);
        return std::nullopt;
    };
    try {
        Recording rec;
        std::map<QString, int> rowOfSample;  // CSV: the line of each sample, for the messages
        if (isCsv(text)) {
            rec = parseCsv(text, csvTable, rowOfSample);
        } else {
            QJsonParseError parseError;
            const QJsonDocument document = QJsonDocument::fromJson(text, &parseError);
            if (parseError.error != QJsonParseError::NoError) {
                const auto [line, column] = lineAndColumn(text, parseError.offset);
                return fail(QString(), QStringLiteral("line %1, column %2: not valid JSON, nor CSV with the header "
                                                      "t,ball,x,y (%3)")
                                           .arg(line)
                                           .arg(column)
                                           .arg(parseError.errorString()));
            }
            if (auto duplicate = findDuplicateKey(text)) refuse(duplicate->path, duplicate->message);
            rec = parseJson(document);
        }
        if (const std::optional<RecordingProblem> problem = recordingProblem(rec)) {
            const QString path = QString::fromStdString(problem->path);
            refuse(rowOfSample.empty() ? path : csvPlace(path, rec, rowOfSample), QString::fromStdString(problem->message));
        }
        return rec;
    } catch (const Refusal& r) {
        return fail(r.path, r.message);
    }
}

std::optional<Recording> loadRecording(const QString& path, QString* error, const TableSpec& csvTable)
{
    const QString name = QFileInfo(path).fileName();
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        if (error) *error = QStringLiteral("%1: cannot read the file (%2)").arg(name, file.errorString());
        return std::nullopt;
    }
    return parseRecording(file.readAll(), name, error, csvTable);
}

QByteArray serializeRecording(const Recording& recording)
{
    JsonWriter w;
    w.beginObject(JsonWriter::Layout::Block);
    w.key("format");
    w.value("cuelab-recording");
    w.key("version");
    w.value(1);
    if (!recording.name.empty()) {
        w.key("name");
        w.value(recording.name);
    }
    if (!recording.source.empty()) {
        w.key("source");
        w.value(recording.source);
    }
    w.key("table");
    w.beginObject();
    w.key("kind");
    w.value(toString(recording.table.kind));
    if (recording.table.length) {
        w.key("length");
        w.value(*recording.table.length);
    }
    if (recording.table.width) {
        w.key("width");
        w.value(*recording.table.width);
    }
    if (recording.table.cushionHeight) {
        w.key("cushion_height");
        w.value(*recording.table.cushionHeight);
    }
    if (!recording.table.pockets) {
        w.key("pockets");
        w.value(false);
    }
    w.endObject();
    w.key("balls");
    w.beginArray(JsonWriter::Layout::Block);
    for (const RecordedBall& b : recording.balls) {
        w.beginObject();
        w.key("id");
        w.value(b.id);
        if (b.radius) {
            w.key("radius");
            w.value(*b.radius);
        }
        w.key("samples");
        w.beginArray();
        for (const RecordedSample& s : b.samples) {
            const double values[3] = {s.time, s.position.x(), s.position.y()};
            w.numbers(values, 3);
        }
        w.endArray();
        w.endObject();
    }
    w.endArray();
    w.endObject();
    return QByteArray::fromStdString(w.text());
}

}  // namespace cuelab::io
