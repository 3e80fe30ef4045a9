#include "ShotCode.h"

#include "KindDefaults.h"
#include "SetupFile.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QtEndian>

#include <zlib.h>

#include <array>
#include <string_view>

namespace cuelab::io {

namespace {

const QString kPrefix = QStringLiteral("cuelab:");
const QString kName = QStringLiteral("shot code");
constexpr qsizetype kMaxText = 16 * 1024 * 1024;  // bytes of setup text a code may unpack to

// Version 1's preset dictionary: the words of a compact setup file (keys in QJsonDocument's order,
// the most common last, where deflate reaches them cheapest). It is part of the format: a code of
// version 1 unpacks only with these bytes, so they never change (tests/io/tst_shotcode pins codes).
constexpr std::string_view kDictionaryV1 =
    "\"game\":{\"group\":\"open\",\"nominated\":\"pocket-tr\",\"on\":\"red\",\"rules\":\"9-ball\"},"
    "\"lesson\":{\"questions\":[{\"balls\":[\"kind\":\"prompt\":\"notes\":\"\","
    "\"simulation\":{\"frame_dt\":0.01,\"max_time\":,\"mass\":0.1,\"radius\":0.0,\"vz\":,\"z\":0.0"
    "\"model\":\"stronge\",\"omega_ratio\":\"model\":\"mirror\",\"model\":\"mathavan2010\",\"steps\":"
    "\"physics\":{\"ball_ball\":{\"friction\":\"alciatore\",\"model\":\"frictional\",\"restitution\":0.9},"
    "\"ball_cushion\":{\"friction\":0.1,\"model\":\"han2005\",\"restitution\":0.8},"
    "\"ball_table\":{\"friction\":0.2,\"model\":\"frictionless\",\"restitution\":0.5},"
    "\"gravity\":9.81,\"mu_roll\":0.00,\"mu_slide\":0.1,\"mu_spin\":0.01},"
    "\"table\":{\"kind\":\"snooker\"}\"table\":{\"kind\":\"pool-7ft\"}\"table\":{\"kind\":\"pool-8ft\"}"
    "\"table\":{\"kind\":\"carom\"},\"version\":1}"
    "{\"id\":\"black\",\"position\":[{\"id\":\"pink\",\"position\":[{\"id\":\"blue\",\"position\":["
    "{\"id\":\"brown\",\"position\":[{\"id\":\"green\",\"position\":[{\"id\":\"yellow\",\"position\":["
    "{\"id\":\"white\",\"position\":[{\"id\":\"red\",\"position\":[{\"id\":\"red-1"
    "{\"id\":\"15\",\"position\":[{\"id\":\"14\",\"position\":[{\"id\":\"13\",\"position\":["
    "{\"id\":\"12\",\"position\":[{\"id\":\"11\",\"position\":[{\"id\":\"10\",\"position\":["
    "{\"id\":\"9\",\"position\":[{\"id\":\"8\",\"position\":[{\"id\":\"7\",\"position\":["
    "{\"id\":\"6\",\"position\":[{\"id\":\"5\",\"position\":[{\"id\":\"4\",\"position\":["
    "{\"id\":\"3\",\"position\":[{\"id\":\"2\",\"position\":[1.{\"id\":\"1\",\"position\":[1.9,0.6"
    "]},\"spin\":[0,0,0],\"velocity\":[0,0]}],\"name\":\"\",\"notes\":\"\","
    "\"shot\":{\"ball\":\"cue\",\"elevation\":0,\"heading\":0,\"height\":0,\"side\":0,\"speed\":2"
    "},\"table\":{\"kind\":\"pool-9ft\"},\"version\":1}"
    "{\"balls\":[{\"id\":\"cue\",\"position\":[0.";

const Bytef* dictionary() { return reinterpret_cast<const Bytef*>(kDictionaryV1.data()); }
uInt dictionarySize() { return static_cast<uInt>(kDictionaryV1.size()); }

// Raw deflate (no zlib header: the code's version says what follows) with the preset dictionary.
QByteArray pack(const QByteArray& text)
{
    z_stream z{};
    if (deflateInit2(&z, Z_BEST_COMPRESSION, Z_DEFLATED, -MAX_WBITS, 9, Z_DEFAULT_STRATEGY) != Z_OK) return {};
    deflateSetDictionary(&z, dictionary(), dictionarySize());
    QByteArray out(static_cast<qsizetype>(deflateBound(&z, static_cast<uLong>(text.size()))), Qt::Uninitialized);
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.constData()));
    z.avail_in = static_cast<uInt>(text.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = static_cast<uInt>(out.size());
    const int status = deflate(&z, Z_FINISH);
    out.resize(static_cast<qsizetype>(z.total_out));
    deflateEnd(&z);
    return status == Z_STREAM_END ? out : QByteArray();
}

// The text again; nullopt when the stream is damaged, cut off, followed by anything, or would unpack
// beyond kMaxText.
std::optional<QByteArray> unpack(const QByteArray& packed)
{
    z_stream z{};
    if (inflateInit2(&z, -MAX_WBITS) != Z_OK) return std::nullopt;
    if (inflateSetDictionary(&z, dictionary(), dictionarySize()) != Z_OK) {
        inflateEnd(&z);
        return std::nullopt;
    }
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(packed.constData()));
    z.avail_in = static_cast<uInt>(packed.size());
    QByteArray text;
    std::array<char, 16384> chunk{};
    int status = Z_OK;
    while (status == Z_OK) {
        z.next_out = reinterpret_cast<Bytef*>(chunk.data());
        z.avail_out = static_cast<uInt>(chunk.size());
        status = inflate(&z, Z_NO_FLUSH);
        if (status != Z_OK && status != Z_STREAM_END) break;
        text.append(chunk.data(), static_cast<qsizetype>(chunk.size() - z.avail_out));
        if (text.size() > kMaxText) break;
        if (status == Z_OK && z.avail_in == 0 && z.avail_out != 0) break;  // cut off: no more input
    }
    const bool whole = status == Z_STREAM_END && z.avail_in == 0;
    inflateEnd(&z);
    if (!whole) return std::nullopt;
    return text;
}

quint32 checksum(const QByteArray& text)
{
    return static_cast<quint32>(crc32(0L, reinterpret_cast<const Bytef*>(text.constData()), static_cast<uInt>(text.size())));
}

// The members of `object` equal to those of `defaults`, left out (nested objects member by member).
QJsonObject withoutDefaults(const QJsonObject& object, const QJsonObject& defaults)
{
    QJsonObject kept;
    for (auto it = object.begin(); it != object.end(); ++it) {
        const QJsonValue d = defaults.value(it.key());
        if (it.value().isObject() && d.isObject()) {
            const QJsonObject inner = withoutDefaults(it.value().toObject(), d.toObject());
            if (!inner.isEmpty()) kept.insert(it.key(), inner);
        } else if (it.value() != d) {
            kept.insert(it.key(), it.value());
        }
    }
    return kept;
}

QString problem(const QString& what) { return QStringLiteral("%1: %2").arg(kName, what); }

}  // namespace

bool isShotCode(const QString& text) { return text.trimmed().startsWith(kPrefix); }

QString shotCode(const Setup& setup)
{
    // The file's own text, compact (QJsonDocument writes every number with its shortest round-trip
    // digits), without the physics the table kind brings anyway and without the format's name.
    QJsonObject root = QJsonDocument::fromJson(serializeSetup(setup)).object();
    Setup plain;
    plain.table = setup.table;
    plain.physics = defaultPhysics(setup.table.kind);
    const QJsonObject defaults = QJsonDocument::fromJson(serializeSetup(plain)).object().value(QStringLiteral("physics")).toObject();
    const QJsonObject physics = withoutDefaults(root.value(QStringLiteral("physics")).toObject(), defaults);
    if (physics.isEmpty()) root.remove(QStringLiteral("physics"));
    else root.insert(QStringLiteral("physics"), physics);
    root.remove(QStringLiteral("format"));
    return shotCodeOfText(QJsonDocument(root).toJson(QJsonDocument::Compact));
}

QString shotCodeOfText(const QByteArray& text)
{
    // The packed text, then its CRC-32 (4 bytes, big-endian): a character changed in copying is
    // caught, never read as another setup.
    QByteArray packed = pack(text);
    std::array<char, 4> crc{};
    qToBigEndian(checksum(text), crc.data());
    packed.append(crc.data(), 4);
    return kPrefix + QString::number(kShotCodeVersion) + QLatin1Char(':') +
           QString::fromLatin1(packed.toBase64(QByteArray::Base64UrlEncoding | QByteArray::OmitTrailingEquals));
}

std::optional<Setup> parseShotCode(const QString& code, QString* error)
{
    const auto refuse = [error](const QString& what) -> std::optional<Setup> {
        if (error) *error = problem(what);
        return std::nullopt;
    };
    const QString text = code.trimmed();
    if (!text.startsWith(kPrefix)) return refuse(QStringLiteral("does not begin with \"cuelab:\""));
    const qsizetype colon = text.indexOf(QLatin1Char(':'), kPrefix.size());
    if (colon < 0) return refuse(QStringLiteral("no version (expected cuelab:%1:...)").arg(kShotCodeVersion));
    bool numeric = false;
    const int version = text.mid(kPrefix.size(), colon - kPrefix.size()).toInt(&numeric);
    if (!numeric) return refuse(QStringLiteral("no version number after \"cuelab:\""));
    if (version != kShotCodeVersion)
        return refuse(QStringLiteral("version %1 is not known to this CueLab (it reads version %2)").arg(version).arg(kShotCodeVersion));
    const QByteArray body = text.mid(colon + 1).toLatin1();
    if (body.isEmpty()) return refuse(QStringLiteral("empty after the version"));
    const auto decoded = QByteArray::fromBase64Encoding(body, QByteArray::Base64UrlEncoding | QByteArray::AbortOnBase64DecodingErrors);
    if (!decoded) return refuse(QStringLiteral("broken: not URL-safe base64 (a character was lost or changed in copying?)"));
    const QByteArray& bytes = *decoded;
    // The unused low bits of the last character are zero in a code as written: anything else was changed.
    if (bytes.toBase64(QByteArray::Base64UrlEncoding | QByteArray::OmitTrailingEquals) != body)
        return refuse(QStringLiteral("broken: its last character was changed"));
    if (bytes.size() < 5) return refuse(QStringLiteral("broken: too short (was it cut off?)"));
    const std::optional<QByteArray> json = unpack(bytes.left(bytes.size() - 4));
    if (!json || checksum(*json) != qFromBigEndian<quint32>(bytes.constData() + bytes.size() - 4))
        return refuse(QStringLiteral("broken: it does not unpack to what it was made from (was it cut off or changed?)"));
    // The setup file's text again, read by the file's reader.
    QJsonParseError parseError;
    const QJsonDocument document = QJsonDocument::fromJson(*json, &parseError);
    if (parseError.error != QJsonParseError::NoError || !document.isObject())
        return refuse(QStringLiteral("broken: it does not hold a setup"));
    QJsonObject root = document.object();
    root.insert(QStringLiteral("format"), QStringLiteral("cuelab-setup"));
    return parseSetup(QJsonDocument(root).toJson(QJsonDocument::Compact), kName, error);
}

}  // namespace cuelab::io
