// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <memory>

#include <QDialog>

#include "model/gcode/dialect.h"
#include "model/job/jobpreparer.h"
#include "ui/job/jobsources.h"

class QCheckBox;
class QDoubleSpinBox;
class QLabel;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace Toffee {

class BackgroundTask;

// Prepare… after a job check: what the preparation would change, side by side with the original (the lines
// around each change), and Save Prepared Program… to write it. For the Carvera: stored TLOs after manual
// changes and a break test after each tool's last cut; for the G43 controllers: the missing G43.
class JobPrepareDialog final : public QDialog
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(JobPrepareDialog)

public:
    JobPrepareDialog(QString program, JobSources sources, Dialect dialect, std::optional<double> zFloor,
        QList<int> rack, QWidget *parent = nullptr);
    ~JobPrepareDialog() override;

    // Runs the preparation for the preview (no file), or into `output`.
    void preview();
    void saveTo(const QString &output);
    [[nodiscard]] bool isRunning() const;
    [[nodiscard]] const std::optional<PrepareSummary> &summary() const { return m_summary; }
    [[nodiscard]] QString savedTo() const { return m_saved; }

Q_SIGNALS:
    void done();

protected:
    void reject() override;

private:
    [[nodiscard]] PrepareOptions options() const;
    void run(const QString &output);
    void finished(bool cancelled);
    void showPreview();
    void save();
    void setRunning(bool running);

    QString m_programPath;
    JobSources m_sources;
    Dialect m_dialect;
    std::optional<double> m_zFloor;
    QList<int> m_rack;
    BackgroundTask *m_task;
    QCheckBox *m_storedTlo = nullptr;
    QCheckBox *m_breakTest = nullptr;
    QDoubleSpinBox *m_tolerance = nullptr;
    QProgressBar *m_progress;
    QPushButton *m_cancel;
    QPushButton *m_save;
    QLabel *m_status;
    QTableWidget *m_preview;
    std::optional<PrepareSummary> m_summary;
    QString m_output; // where the running preparation writes; empty for a preview
    QString m_saved;
    std::shared_ptr<Result<PrepareSummary>> m_result;
};

} // namespace Toffee
