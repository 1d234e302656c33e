// SPDX-License-Identifier: GPL-3.0-or-later
// HSMWorks / Fusion .hsmlib tool libraries (FORMATS.md): XML, usually UTF-16 with a byte-order mark, decoded
// and checked against the reader's bounds by XmlText first. Only tool/@unit, @type, description, nc/@number
// and @length-offset (for a note), body/@diameter, @flute-length, @overall-length are read; motion, coolant
// and the holder are not offsets.
#include <memory>

#include <QCoreApplication>
#include <QHash>
#include <QXmlStreamReader>

#include "model/camimport/camreaders.h"
#include "model/camimport/xmltext.h"
#include "model/textparsing.h"
#include "model/translate.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr auto kNamespace = "http://www.hsmworks.com/xml/2004/cnc/tool-library"_L1;

// Translates in its own context: lupdate files a class's tr() under the class, never under "Toffee".
class HsmReader
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::HsmReader)

public:
    explicit HsmReader(std::unique_ptr<QXmlStreamReader> reader)
        : m_reader(std::move(reader))
    { }

    Result<QList<CamTool>> read()
    {
        if (!m_xml.readNextStartElement())
            return xmlError(tr("there is no XML element in it"));
        if (!isOurs(u"tool-library"_s) && !isOurs(u"tool-table"_s))
            return Error { tr("column %1: this is not an HSM tool library: its root element is <%2> in "
                              "namespace \"%3\", where a library has <tool-library> in \"%4\".")
                               .arg(m_xml.columnNumber())
                               .arg(excerpt(m_xml.name()), excerpt(m_xml.namespaceUri()), kNamespace),
                int(m_xml.lineNumber()) };
        QList<CamTool> tools;
        while (m_xml.readNextStartElement()) {
            if (!isOurs(u"tool"_s)) {
                m_xml.skipCurrentElement();
                continue;
            }
            auto tool = readTool(tools.size() + 1);
            if (!tool)
                return tool.error();
            tools.append(tool.takeValue());
        }
        // The rest of the document must be well-formed too: a library cut short is refused, not half read.
        while (!m_xml.atEnd())
            m_xml.readNext();
        if (m_xml.hasError())
            return xmlError(m_xml.errorString());
        return checkCamTools(std::move(tools));
    }

private:
    [[nodiscard]] bool isOurs(const QString &name) const
    {
        return m_xml.name() == name && m_xml.namespaceUri() == kNamespace;
    }

    Error xmlError(const QString &reason) const
    {
        return Error {
            tr("column %1: this is not well-formed XML (%2).").arg(m_xml.columnNumber()).arg(reason),
            int(m_xml.lineNumber())
        };
    }

    // The reader is at <tool>; it ends at </tool>.
    Result<CamTool> readTool(qsizetype index)
    {
        CamTool tool;
        tool.place = tr("tool %1").arg(index);
        tool.line = int(m_xml.lineNumber());
        tool.type = m_xml.attributes().value(u"type"_s).toString();
        const QStringView unit = m_xml.attributes().value(u"unit"_s);
        if (unit == u"millimeters"_s || unit == u"mm"_s)
            tool.units = Units::Millimetre;
        else if (unit == u"inches"_s || unit == u"in"_s)
            tool.units = Units::Inch;
        else
            return refuse(
                tool, tr("its unit is \"%1\"; Toffee reads millimeters or inches.").arg(excerpt(unit)));
        // The line of each element read once: a second one would silently replace the first.
        QHash<QString, qint64> seen;
        while (m_xml.readNextStartElement()) {
            const QString name = m_xml.name().toString();
            const bool read = name == u"description"_s || name == u"nc"_s || name == u"body"_s;
            if (read) {
                if (const auto first = seen.constFind(name); first != seen.cend())
                    return refuse(tool,
                        tr("it has a second <%1> (the first is on line %2); a tool has one, and Toffee will "
                           "not guess which one is meant.")
                            .arg(name)
                            .arg(*first));
                seen.insert(name, m_xml.lineNumber());
            }
            if (name == u"description"_s) {
                tool.description = m_xml.readElementText(QXmlStreamReader::IncludeChildElements);
                continue;
            }
            bool ok = true;
            if (name == u"nc"_s)
                ok = readNumber(tool) && readLengthOffset(tool);
            else if (name == u"body"_s)
                ok = length(u"diameter"_s, tool.diameter) && length(u"flute-length"_s, tool.fluteLength)
                    && length(u"overall-length"_s, tool.overallLength);
            if (!ok)
                return refuse(tool, m_why);
            m_xml.skipCurrentElement();
        }
        if (m_xml.hasError())
            return xmlError(m_xml.errorString());
        if (!m_hasNumber)
            return refuse(tool, tr("it has no <nc number=…>: Toffee needs the T number the post writes."));
        m_hasNumber = false;
        return tool;
    }

    Error refuse(const CamTool &tool, const QString &why) const
    {
        return Error { tool.place + u": "_s + why, int(m_xml.lineNumber()) };
    }

    bool readNumber(CamTool &tool)
    {
        const QString text = m_xml.attributes().value(u"number"_s).toString();
        const auto number = parseInteger(text.toUtf8());
        if (!number || *number < -1'000'000'000 || *number > 1'000'000'000) {
            m_why = tr("its nc number is \"%1\", not a tool number.").arg(excerpt(text));
            return false;
        }
        tool.number = int(*number);
        m_hasNumber = true;
        return true;
    }

    // Only for the preview's note: Toffee's H is always T.
    bool readLengthOffset(CamTool &tool)
    {
        const QXmlStreamAttributes attributes = m_xml.attributes();
        if (!attributes.hasAttribute(u"length-offset"_s))
            return true;
        const QString text = attributes.value(u"length-offset"_s).toString();
        const auto offset = parseInteger(text.trimmed().toUtf8());
        if (!offset || *offset < -1'000'000'000 || *offset > 1'000'000'000) {
            m_why = tr("its nc length-offset is \"%1\", not a whole number.").arg(excerpt(text));
            return false;
        }
        tool.lengthOffset = int(*offset);
        return true;
    }

    bool length(const QString &name, std::optional<double> &out)
    {
        const QXmlStreamAttributes attributes = m_xml.attributes();
        if (!attributes.hasAttribute(name))
            return true;
        const QString text = attributes.value(name).toString();
        out = parseDecimal(text.trimmed().toUtf8());
        if (!out)
            m_why = tr("its body %1 is \"%2\", not a number.").arg(name, excerpt(text));
        return out.has_value();
    }

    std::unique_ptr<QXmlStreamReader> m_reader;
    QXmlStreamReader &m_xml = *m_reader;
    QString m_why;
    bool m_hasNumber = false;
};

} // namespace

Result<QList<CamTool>> readHsmLibrary(QByteArrayView xml)
{
    auto text = XmlText::read(xml);
    if (!text)
        return text.error();
    return HsmReader(std::move(text.value()).reader()).read();
}

} // namespace Toffee
