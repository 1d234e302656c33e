// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QDialog>

class QLabel;
class QTextBrowser;

namespace Toffee {

// Help ▸ User's Guide (F1): the installed docs/GUIDE.md, rendered in the window with its screenshots. A link
// to a page not installed with Toffee says so instead of showing nothing.
class GuideDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(GuideDialog)

public:
    // `path`: the guide's file (guidePath() unless a test says otherwise).
    explicit GuideDialog(const QString &path, QWidget *parent = nullptr);

    [[nodiscard]] bool loaded() const { return m_loaded; }
    [[nodiscard]] QTextBrowser *browser() const { return m_browser; }

private:
    void follow(const QUrl &link);
    void fitImages();
    static constexpr int kPageWidth = 790; // px: the dialog's 900 less its margins and scroll bar

    QTextBrowser *m_browser;
    QLabel *m_note;
    bool m_loaded = false;
};

// Opens the guide, or says where it should have been and what to do.
void showGuide(QWidget *parent);

} // namespace Toffee
