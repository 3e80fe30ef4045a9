#include "JsonDuplicateKeys.h"

#include <QHash>
#include <QJsonArray>
#include <QJsonDocument>
#include <QString>

#include <vector>

namespace cuelab::io {

namespace {

// One open object or array while walking the text.
struct Container {
    bool isObject = false;
    QString path;                      // JSON path of the container itself
    QHash<QString, qsizetype> keys;    // object: key -> byte offset of its first appearance
    qsizetype index = 0;               // array: index of the current element
    bool expectKey = true;             // object: the next string is a key
    QString key;                       // object: the key of the current member
};

QString childPath(const Container& c)
{
    if (c.isObject) return c.path.isEmpty() ? c.key : c.path + QLatin1Char('.') + c.key;
    return c.path + QStringLiteral("[%1]").arg(c.index);
}

// The decoded text of the string token starting at `begin` (a quote); `end` is set past its
// closing quote. Escapes are rare in keys, so only then is Qt asked to decode.
QString readString(const QByteArray& json, qsizetype begin, qsizetype& end)
{
    bool escaped = false;
    qsizetype i = begin + 1;
    while (i < json.size() && json[i] != '"') {
        if (json[i] == '\\') {
            escaped = true;
            ++i;
        }
        ++i;
    }
    end = i + 1;
    const QByteArray token = json.mid(begin, end - begin);
    if (!escaped) return QString::fromUtf8(token.mid(1, token.size() - 2));
    return QJsonDocument::fromJson("[" + token + "]").array().at(0).toString();
}

int lineOf(const QByteArray& json, qsizetype offset) { return 1 + int(json.left(offset).count('\n')); }

}  // namespace

std::optional<SetupProblem> findDuplicateKey(const QByteArray& json)
{
    std::vector<Container> open;
    qsizetype i = 0;
    const qsizetype n = json.size();
    while (i < n) {
        const char c = json[i];
        switch (c) {
        case '{':
        case '[': {
            Container next;
            next.isObject = c == '{';
            next.path = open.empty() ? QString() : childPath(open.back());
            open.push_back(std::move(next));
            ++i;
            break;
        }
        case '}':
        case ']':
            if (!open.empty()) open.pop_back();
            ++i;
            break;
        case ',':
            if (!open.empty() && open.back().isObject) open.back().expectKey = true;
            else if (!open.empty()) ++open.back().index;
            ++i;
            break;
        case '"': {
            if (open.empty()) return std::nullopt;  // not a document of objects and arrays
            qsizetype end = 0;
            const QString text = readString(json, i, end);
            Container& here = open.back();
            if (here.isObject && here.expectKey) {
                here.key = text;
                here.expectKey = false;
                const auto first = here.keys.constFind(text);
                if (first != here.keys.constEnd())
                    return SetupProblem{childPath(here), QStringLiteral("duplicate key (the first one is on line %1)")
                                                             .arg(lineOf(json, *first))};
                here.keys.insert(text, i);
            }
            i = end;
            break;
        }
        default: ++i;  // whitespace, ':', numbers, true, false, null
        }
    }
    return std::nullopt;
}

}  // namespace cuelab::io
