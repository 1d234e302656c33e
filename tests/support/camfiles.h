// SPDX-License-Identifier: GPL-3.0-or-later
// CAM tool libraries for the import tests, written here from the facts in FORMATS.md: Fusion JSON, a .tools
// zip archive (made with libzip), a UTF-16 .hsmlib with its byte-order mark, a program with Makera's header.
#pragma once

#include <zip.h>

#include <QByteArray>
#include <QFile>
#include <QStringEncoder>
#include <QTemporaryDir>
#include <QTest>

namespace Toffee::Test {

// One Fusion tool with every kind of member a real one has; `geometry` replaces the cutter's geometry.
inline QByteArray fusionTool(int number, const QByteArray &description = "6 mm flat",
    const QByteArray &unit = "millimeters",
    const QByteArray &geometry = R"("DC": 6, "SFDM": 6, "OAL": 50, "LCF": 20, "LB": 30, "NOF": 3, "RE": 0,
        "assemblyGaugeLength": 123.4)")
{
    return R"({"guid": "0b1c2d3e-)" + QByteArray::number(number) + R"(", "type": "flat end mill", "unit": ")"
        + unit + R"(", "description": ")" + description
        + R"(", "vendor": "Acme", "product-id": "FE-6", "BMC": "carbide",
      "geometry": {)"
        + geometry + R"(},
      "post-process": {"number": )"
        + QByteArray::number(number) + R"(, "turret": 0, "length-offset": )" + QByteArray::number(number)
        + R"(, "diameter-offset": )" + QByteArray::number(number)
        + R"(, "break-control": true, "manual-tool-change": false, "live": true, "comment": ""},
      "holder": {"description": "ER11", "segments": [{"height": 20, "lower-diameter": 16}]},
      "start-values": {"presets": [{"n": 18000, "v_f": 800}]}})";
}

// {"version": …, "data": [tool, …]}: the header on lines 1-2, each tool from a line of its own.
inline QByteArray fusionLibrary(const QList<QByteArray> &tools)
{
    QByteArray out = "{\n  \"version\": 14,\n  \"data\": [\n";
    for (qsizetype i = 0; i < tools.size(); ++i)
        out += "    " + tools.at(i) + (i + 1 < tools.size() ? ",\n" : "\n");
    return out + "  ]\n}\n";
}

// A zip archive holding `entries` (name, contents), compressed as Fusion's are.
inline QByteArray zipArchive(const QList<std::pair<QByteArray, QByteArray>> &entries)
{
    QTemporaryDir dir;
    const QByteArray path = QFile::encodeName(dir.filePath(QStringLiteral("archive.zip")));
    int error = 0;
    zip_t *archive = zip_open(path.constData(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    if (!archive)
        return {};
    for (const auto &[name, contents] : entries) {
        // libzip reads the buffer at zip_close(): `entries` is alive until then.
        zip_source_t *source
            = zip_source_buffer(archive, contents.constData(), zip_uint64_t(contents.size()), 0);
        if (!source || zip_file_add(archive, name.constData(), source, ZIP_FL_ENC_UTF_8) < 0) {
            zip_source_free(source);
            zip_discard(archive);
            return {};
        }
    }
    if (zip_close(archive) != 0) {
        zip_discard(archive);
        return {};
    }
    QFile file(dir.filePath(QStringLiteral("archive.zip")));
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

inline constexpr char kHsmNamespace[] = "http://www.hsmworks.com/xml/2004/cnc/tool-library";

// One .hsmlib tool: <tool> with description, nc, body and the parts that are not offsets.
inline QString hsmTool(int number, const QString &body = QStringLiteral(R"(diameter="6" corner-radius="0"
        flute-length="20" shaft-diameter="6" overall-length="50" number-of-flutes="3")"),
    const QString &unit = QStringLiteral("millimeters"),
    const QString &description = QStringLiteral("6 mm flat"))
{
    return QStringLiteral(R"(  <tool guid="{a-%1}" type="flat end mill" unit="%2">
    <description>%3</description>
    <nc number="%1" length-offset="%1" diameter-offset="%1" turret="0" break-control="yes" manual-tool-change="no"/>
    <coolant mode="flood"/>
    <body %4/>
    <motion spindle-rpm="18000" cutting-feedrate="800"/>
    <holder><section diameter="16" length="20"/></holder>
  </tool>
)")
        .arg(QString::number(number), unit, description, body);
}

// A whole .hsmlib in UTF-16 (little-endian, with the byte-order mark), as HSMWorks and Fusion write it.
inline QByteArray hsmLibrary(const QString &tools, const QString &root = QStringLiteral("tool-library"),
    const QString &ns = QString::fromLatin1(kHsmNamespace))
{
    const QString xml = QStringLiteral("<?xml version=\"1.0\" encoding=\"UTF-16\"?>\n<%1 xmlns=\"%2\" "
                                       "version=\"18\">\n%3</%1>\n")
                            .arg(root, ns, tools);
    QStringEncoder encoder(QStringEncoder::Utf16LE, QStringEncoder::Flag::WriteBom);
    return encoder.encode(xml);
}

// A program as Makera CAM writes it: comments, the tool header, then the body.
inline QByteArray makeraProgram(
    const QList<QByteArray> &toolLines, const QByteArray &body = "G21\nG90\nT3 M6\n")
{
    QByteArray out = ";Makera CAM 1.2\n;Post: Carvera\n";
    for (const QByteArray &line : toolLines)
        out += line + '\n';
    return out + "\n" + body;
}

inline QByteArray makeraTool(
    int number, const QByteArray &extra = "diameter=3.175|flutelength=12|sticklength=18")
{
    return ";@MKR|TOOL|number=" + QByteArray::number(number) + "|id=17|name=Flat "
        + QByteArray::number(number) + "|type=flat end mill|handlediameter=3.175|shoulderlength=14|" + extra
        + "|tipdiameter=0|cornerradius=0|angle=0|halfAngle=0";
}

inline bool writeFile(const QString &path, const QByteArray &data)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly) && file.write(data) == data.size();
}

} // namespace Toffee::Test
