// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/shell/guidedialog.h"

#include <QDesktopServices>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QPushButton>
#include <QTextBlock>
#include <QTextBrowser>
#include <QTextCursor>
#include <QVBoxLayout>

#include "model/modules.h"

using namespace Qt::StringLiterals;

namespace Toffee {

GuideDialog::GuideDialog(const QString &path, QWidget *parent)
    : QDialog(parent)
    , m_browser(new QTextBrowser(this))
    , m_note(new QLabel(this))
{
    setObjectName(u"guideDialog"_s);
    setWindowTitle(tr("Toffee's User's Guide"));
    m_browser->setObjectName(u"guideBrowser"_s);
    m_browser->setOpenLinks(false);
    connect(m_browser, &QTextBrowser::anchorClicked, this, &GuideDialog::follow);
    m_note->setObjectName(u"guideNote"_s);
    m_note->setWordWrap(true);
    m_note->hide();
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_browser);
    layout->addWidget(m_note);
    layout->addWidget(buttons);
    resize(900, 700);
    const QFileInfo file(path);
    if (file.isFile() && file.isReadable()) {
        m_browser->setSearchPaths({ file.absolutePath() });
        m_browser->setSource(QUrl::fromLocalFile(file.absoluteFilePath()), QTextDocument::MarkdownResource);
        m_loaded = !m_browser->document()->isEmpty();
        fitImages();
    }
}

// Screenshots are 1280 px wide: shown at most as wide as the page, at their own proportions.
void GuideDialog::fitImages()
{
    QTextDocument *document = m_browser->document();
    for (QTextBlock block = document->begin(); block.isValid(); block = block.next()) {
        for (auto it = block.begin(); !it.atEnd(); ++it) {
            const QTextFragment fragment = it.fragment();
            if (!fragment.charFormat().isImageFormat())
                continue;
            QTextImageFormat image = fragment.charFormat().toImageFormat();
            const QImage picture
                = document->resource(QTextDocument::ImageResource, QUrl(image.name())).value<QImage>();
            if (picture.isNull() || picture.width() <= kPageWidth)
                continue;
            image.setWidth(kPageWidth);
            image.setHeight(double(picture.height()) * kPageWidth / picture.width());
            QTextCursor cursor(document);
            cursor.setPosition(fragment.position());
            cursor.setPosition(fragment.position() + fragment.length(), QTextCursor::KeepAnchor);
            cursor.setCharFormat(image);
        }
    }
}

void GuideDialog::follow(const QUrl &link)
{
    if (link.scheme().startsWith(u"http"_s)) {
        QDesktopServices::openUrl(link);
        return;
    }
    if (link.path().isEmpty()) { // a heading of this page
        m_browser->scrollToAnchor(link.fragment());
        return;
    }
    const QUrl target = m_browser->source().resolved(link);
    if (target.isLocalFile() && QFileInfo(target.toLocalFile()).isFile()) {
        m_browser->setSource(target, QTextDocument::MarkdownResource);
        fitImages();
        m_note->hide();
        return;
    }
    m_note->setText(
        tr("%1 is not installed with Toffee: it is in the docs folder of Toffee's source.").arg(link.path()));
    m_note->show();
}

void showGuide(QWidget *parent)
{
    const QString path = guidePath();
    auto *guide = new GuideDialog(path, parent);
    guide->setAttribute(Qt::WA_DeleteOnClose);
    if (!guide->loaded()) {
        delete guide;
        QMessageBox::warning(parent, GuideDialog::tr("The user's guide is missing"),
            GuideDialog::tr(
                "The user's guide is not where Toffee installs it (%1). Reinstall Toffee's package, "
                "or read docs/GUIDE.md in its source.")
                .arg(path));
        return;
    }
    guide->show(); // beside the window, not in its way: the operator reads it while working
}

} // namespace Toffee
