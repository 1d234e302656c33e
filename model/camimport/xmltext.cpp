// SPDX-License-Identifier: GPL-3.0-or-later
#include "model/camimport/xmltext.h"

#include <cstring>
#include <optional>
#include <vector>

#include <QStringDecoder>
#include <QXmlStreamReader>

#include "model/textparsing.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

// The encoding an XML file's first bytes give (XML 1.0 Appendix F): a byte-order mark, or UTF-16 or UTF-32
// by where the zero bytes of its first character are (00 3C 00 3F is "<?" in UTF-16BE). Nothing for UTF-8
// and the encodings in which the declaration is ASCII.
std::optional<QStringConverter::Encoding> encodingOfFirstBytes(QByteArrayView data)
{
    const auto startsWith = [data](const char *bytes, qsizetype size) {
        return data.startsWith(QByteArrayView(bytes, size));
    };
    const auto zero = [data](qsizetype at) {
        return data.at(at) == '\0';
    };
    if (startsWith("\x00\x00\xfe\xff", 4))
        return QStringConverter::Utf32BE;
    if (startsWith("\xff\xfe\x00\x00", 4))
        return QStringConverter::Utf32LE;
    if (startsWith("\xfe\xff", 2))
        return QStringConverter::Utf16BE;
    if (startsWith("\xff\xfe", 2))
        return QStringConverter::Utf16LE;
    if (data.size() >= 4 && zero(0) && zero(1) && zero(2) && !zero(3))
        return QStringConverter::Utf32BE;
    if (data.size() >= 4 && !zero(0) && zero(1) && zero(2) && zero(3))
        return QStringConverter::Utf32LE;
    if (data.size() >= 2 && zero(0) && !zero(1))
        return QStringConverter::Utf16BE;
    if (data.size() >= 2 && !zero(0) && zero(1))
        return QStringConverter::Utf16LE;
    return std::nullopt;
}

// The encoding an ASCII declaration names (<?xml version="1.0" encoding="…"?>), or nothing.
QByteArrayView declaredEncoding(QByteArrayView data)
{
    if (!data.startsWith("<?xml"))
        return {};
    const qsizetype end = data.first(std::min<qsizetype>(data.size(), 1024)).indexOf("?>");
    const QByteArrayView declaration = data.first(std::max<qsizetype>(end, 0));
    qsizetype at = declaration.indexOf("encoding");
    if (at < 0)
        return {};
    at += qsizetype(std::strlen("encoding"));
    const auto skipBlanks = [&declaration, &at] {
        while (at < declaration.size() && std::strchr(" \t\r\n", declaration.at(at)))
            ++at;
    };
    skipBlanks();
    if (at >= declaration.size() || declaration.at(at) != '=')
        return {};
    ++at;
    skipBlanks();
    if (at >= declaration.size() || (declaration.at(at) != '"' && declaration.at(at) != '\''))
        return {};
    const qsizetype close = declaration.indexOf(declaration.at(at), at + 1);
    return close < 0 ? QByteArrayView() : declaration.sliced(at + 1, close - at - 1);
}

char32_t unit(char c)
{
    return uchar(c);
}
char32_t unit(QChar c)
{
    return c.unicode();
}

// One pass over the text with the markup an XML parser sees (tags, comments, instructions, CDATA), counting
// what the bounds limit. It only has to agree with QXmlStreamReader on text that is well-formed up to the
// point: QXmlStreamReader never reads past its first error.
template<typename View> class BoundsScan
{
public:
    explicit BoundsScan(View text)
        : m_text(text)
    { }

    Result<void> run()
    {
        while (m_at < m_text.size()) {
            if (at(m_at) != '<') {
                advance();
            } else if (startsWith("<?")) {
                skipPast("?>");
            } else if (startsWith("<!--")) {
                skipPast("-->");
            } else if (startsWith("<![CDATA[")) {
                skipPast("]]>");
            } else if (startsWith("<!DOCTYPE")) {
                return Error { XmlText::tr(
                                   "this is not an HSM tool library Toffee reads: it has a document type "
                                   "declaration (<!DOCTYPE>), which no HSM library has and whose "
                                   "declarations can make reading take hours."),
                    m_line };
            } else if (startsWith("</")) {
                skipPast(">");
                if (!m_open.empty()) {
                    m_namespaces -= m_open.back();
                    m_open.pop_back();
                }
            } else if (auto started = startTag(); !started) {
                return started;
            }
        }
        return {};
    }

private:
    [[nodiscard]] char32_t at(qsizetype i) const { return i < m_text.size() ? unit(m_text[i]) : 0; }
    [[nodiscard]] bool startsWith(const char *ascii) const
    {
        for (qsizetype i = 0; ascii[i]; ++i) {
            if (at(m_at + i) != char32_t(uchar(ascii[i])))
                return false;
        }
        return true;
    }
    [[nodiscard]] static bool isBlank(char32_t c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

    // One unit on; lines end at LF, CR LF or a lone CR, as QXmlStreamReader counts them.
    void advance()
    {
        const char32_t c = at(m_at++);
        if (c == '\n' || (c == '\r' && at(m_at) != '\n'))
            ++m_line;
    }
    void skipPast(const char *end)
    {
        while (m_at < m_text.size() && !startsWith(end))
            advance();
        m_at = std::min(m_text.size(), m_at + qsizetype(std::strlen(end)));
    }

    // At a start tag's '<': its attributes (one '=' each outside quoted values), the namespaces it declares
    // (xmlns="…", xmlns:p="…") and, unless it closes itself, one more element open.
    Result<void> startTag()
    {
        const int line = m_line;
        const qsizetype nameStart = ++m_at;
        while (m_at < m_text.size() && !isBlank(at(m_at)) && at(m_at) != '>' && at(m_at) != '/')
            advance();
        const QString name = excerpt(m_text.sliced(nameStart, m_at - nameStart));
        int attributes = 0;
        int declarations = 0;
        char32_t quote = 0;
        char32_t last = 0;
        qsizetype token = -1;
        for (; m_at < m_text.size(); advance()) {
            const char32_t c = at(m_at);
            if (quote) {
                quote = c == quote ? 0 : quote;
                continue;
            }
            if (c == '>')
                break;
            if (isBlank(c)) {
                token = -1;
                continue;
            }
            last = c;
            if (c == '"' || c == '\'') {
                quote = c;
            } else if (c == '=') {
                if (++attributes > XmlText::kMaxAttributes)
                    return Error { XmlText::tr("this is not an HSM tool library Toffee reads: <%1> has more "
                                               "than %2 attributes; an element of an HSM library has a few "
                                               "dozen at most.")
                                       .arg(name)
                                       .arg(XmlText::kMaxAttributes),
                        line };
                if (token >= 0 && isDeclaration(token))
                    ++declarations;
                token = -1;
            } else if (token < 0) {
                token = m_at;
            }
        }
        if (m_at >= m_text.size())
            return {}; // cut short: the reader says so
        advance();
        m_namespaces += declarations;
        if (m_namespaces > XmlText::kMaxNamespaces)
            return Error { XmlText::tr("this is not an HSM tool library Toffee reads: <%1> brings the XML "
                                       "namespaces declared to %2; an HSM library declares one, and Toffee "
                                       "reads up to %3.")
                               .arg(name)
                               .arg(m_namespaces)
                               .arg(XmlText::kMaxNamespaces),
                line };
        if (last == '/') {
            m_namespaces -= declarations;
            return {};
        }
        if (m_open.size() >= size_t(XmlText::kMaxDepth))
            return Error { XmlText::tr(
                               "this is not an HSM tool library Toffee reads: <%1> is nested %2 "
                               "elements deep; an HSM library nests a few, and Toffee reads up to %3.")
                               .arg(name)
                               .arg(m_open.size() + 1)
                               .arg(XmlText::kMaxDepth),
                line };
        m_open.push_back(declarations);
        return {};
    }

    // Whether the attribute name from `token` is xmlns or xmlns:prefix.
    [[nodiscard]] bool isDeclaration(qsizetype token) const
    {
        static constexpr char kXmlns[] = "xmlns";
        for (qsizetype i = 0; kXmlns[i]; ++i) {
            if (at(token + i) != char32_t(kXmlns[i]))
                return false;
        }
        const char32_t after = at(token + 5);
        return after == ':' || after == '=' || isBlank(after);
    }

    View m_text;
    qsizetype m_at = 0;
    int m_line = 1;
    std::vector<int> m_open; // the namespaces each open element declared
    int m_namespaces = 0;
};

} // namespace

Result<XmlText> XmlText::read(QByteArrayView data)
{
    XmlText text;
    auto encoding = encodingOfFirstBytes(data);
    const QByteArrayView declared = encoding ? QByteArrayView() : declaredEncoding(data);
    const bool utf8 = !encoding
        && (declared.isEmpty() || declared.compare("UTF-8", Qt::CaseInsensitive) == 0
            || declared.compare("UTF8", Qt::CaseInsensitive) == 0);
    if (utf8) {
        text.m_bytes = data;
        if (auto bounded = BoundsScan<QByteArrayView>(data).run(); !bounded)
            return bounded.error();
        return text;
    }
    QStringDecoder decoder = encoding
        ? QStringDecoder(*encoding, QStringDecoder::Flag::Stateless)
        : QStringDecoder(declared.toByteArray().constData(), QStringDecoder::Flag::Stateless);
    if (!decoder.isValid())
        return Error { tr("this is not an HSM tool library Toffee reads: it is in \"%1\", an encoding Toffee "
                          "does not know; save it as UTF-16 or UTF-8.")
                           .arg(excerpt(declared)),
            1 };
    text.m_decoded = decoder.decode(data);
    text.m_isDecoded = true;
    if (decoder.hasError()) {
        // The decoder marks what it could not read with U+FFFD: the first one is on the line to look at.
        const qsizetype bad = std::max<qsizetype>(text.m_decoded.indexOf(QChar::ReplacementCharacter), 0);
        return Error { tr("this is not well-formed XML: it is not valid %1 text.")
                           .arg(QLatin1StringView(decoder.name())),
            int(text.m_decoded.first(bad).count(u'\n')) + 1 };
    }
    if (auto bounded = BoundsScan<QStringView>(text.m_decoded).run(); !bounded)
        return bounded.error();
    return text;
}

std::unique_ptr<QXmlStreamReader> XmlText::reader() &&
{
    if (!m_isDecoded)
        return std::make_unique<QXmlStreamReader>(QByteArray::fromRawData(m_bytes.data(), m_bytes.size()));
    // The reader keeps its own copy of a string, so this one goes once the reader has it.
    const QString decoded = std::move(m_decoded);
    return std::make_unique<QXmlStreamReader>(decoded);
}

} // namespace Toffee
