// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>
#include <optional>

#include <QDialog>

#include "model/job/jobreport.h"
#include "ui/job/jobsources.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QTableView;

namespace Toffee {

class BackgroundTask;
class JobFindingsModel;
class JobToolsModel;

// File ▸ Check Job…: a program checked against the open table and the history library, off the window's
// thread, with progress and Cancel. The tools in order of use, the findings by line (double-click one to see
// the program around it), and Prepare… once it ran through.
class JobCheckDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(JobCheckDialog)

public:
    using Sources = JobSources;

    JobCheckDialog(Sources sources, QWidget *parent = nullptr);
    ~JobCheckDialog() override;

    // What the next check reads (the window's table as it is now, …).
    void setSources(Sources sources);
    // Checks `path`; a check already running is cancelled first.
    void check(const QString &path);
    void cancel();
    [[nodiscard]] bool isRunning() const;
    [[nodiscard]] const std::optional<JobReport> &report() const { return m_report; }
    [[nodiscard]] QString program() const { return m_path; }
    // The program around a finding's line, as a double-click shows it.
    void showLine(int line);

Q_SIGNALS:
    // A check ended: done, cancelled or refused.
    void checked();

protected:
    void reject() override;

private:
    void buildControls();
    void finished(bool cancelled);
    void showReport();
    void setRunning(bool running);
    void prepare();
    void updatePrepare();
    void saveSettings();
    // The options changed: what is shown is no longer what they would find.
    void optionsChanged();
    [[nodiscard]] std::optional<QList<int>> rack() const;

    Sources m_sources;
    BackgroundTask *m_task;
    JobToolsModel *m_toolsModel;
    JobFindingsModel *m_findingsModel;
    QComboBox *m_dialect;
    QCheckBox *m_useFloor;
    QDoubleSpinBox *m_floor;
    QLineEdit *m_rack;
    QLabel *m_program;
    QProgressBar *m_progress;
    QPushButton *m_cancel;
    QPushButton *m_again;
    QPushButton *m_prepare;
    QLabel *m_summary;
    QTableView *m_tools;
    QTableView *m_findings;
    QPlainTextEdit *m_excerpt;
    QString m_path;
    QString m_pending; // a program to check once the running check has stopped
    std::optional<JobReport> m_report;
    std::shared_ptr<Result<JobReport>> m_result; // written by the check's thread, read once it finished
};

} // namespace Toffee
