// SPDX-License-Identifier: GPL-3.0-or-later
// An XML file's text as QXmlStreamReader is given it: in an encoding it reads right, and within the bounds
// that keep its reading as long as the file. Not part of the model's interface.
#pragma once

#include <memory>

#include <QByteArrayView>
#include <QCoreApplication>
#include <QString>

#include "model/result.h"

class QXmlStreamReader;

namespace Toffee {

class XmlText
{
    Q_DECLARE_TR_FUNCTIONS(Toffee::XmlText)

public:
    // QXmlStreamReader compares each attribute with every earlier one of its element, resolves each name by
    // searching every namespace declaration in scope, and matches each element against every attribute
    // default a DTD declares: 120,000 attributes on one element (1.3 MB) took 29 s. Elements of an HSM
    // library have a few dozen attributes, nest a few deep and declare one namespace, and no library has a
    // DTD; these bounds make any file up to kMaxCamLibraryBytes cost at most a few times a plain one.
    static constexpr int kMaxAttributes = 256; // on one element
    static constexpr int kMaxDepth = 64; // elements open at once
    static constexpr int kMaxNamespaces = 16; // namespace declarations in scope at once

    // The text of `data`, which must outlive it, or why it cannot be read (an encoding, a bound) with its
    // line: checked by one pass over the text before any of it is parsed.
    [[nodiscard]] static Result<XmlText> read(QByteArrayView data);

    // A reader over the text; the decoded copy, if there is one, is handed to it.
    [[nodiscard]] std::unique_ptr<QXmlStreamReader> reader() &&;

private:
    XmlText() = default;

    QByteArrayView m_bytes; // UTF-8, given to the reader as they are
    // Any other encoding, decoded here: QXmlStreamReader misreads UTF-16BE without a byte-order mark, and an
    // encoding such as UTF-7 could hide markup from a scan of the bytes.
    QString m_decoded;
    bool m_isDecoded = false;
};

} // namespace Toffee
