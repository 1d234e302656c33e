// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/job/jobpreparedialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

#include "model/job/jobchecker.h"
#include "model/job/jobprepare.h"
#include "model/limits.h"
#include "ui/common/appearance.h"
#include "ui/common/appsettings.h"
#include "ui/common/backgroundtask.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

enum PreviewColumn {
    OriginalLineColumn,
    OriginalColumn,
    PreparedLineColumn,
    PreparedColumn,
    PreviewColumnCount
};

QTableWidgetItem *cell(const QString &text, const QColor &background = {})
{
    auto *item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    if (background.isValid())
        item->setBackground(background);
    return item;
}

// The suggested name for the prepared program: beside the original, "job.nc" → "job.prepared.nc".
QString preparedName(const QString &program)
{
    const QFileInfo info(program);
    return info.dir().filePath(info.completeBaseName() + u".prepared."_s + info.suffix());
}

} // namespace

JobPrepareDialog::JobPrepareDialog(QString program, JobSources sources, Dialect dialect,
    std::optional<double> zFloor, QList<int> rack, QWidget *parent)
    : QDialog(parent)
    , m_programPath(std::move(program))
    , m_sources(std::move(sources))
    , m_dialect(dialect)
    , m_zFloor(zFloor)
    , m_rack(std::move(rack))
    , m_task(new BackgroundTask(this))
    , m_progress(new QProgressBar(this))
    , m_cancel(new QPushButton(tr("Cancel"), this))
    , m_save(new QPushButton(tr("&Save Prepared Program…"), this))
    , m_status(new QLabel(this))
    , m_preview(new QTableWidget(0, PreviewColumnCount, this))
{
    setObjectName(u"jobPrepareDialog"_s);
    setWindowTitle(
        tr("Prepare %1 for %2").arg(QFileInfo(m_programPath).fileName(), dialectInfo(dialect).name));
    auto *layout = new QVBoxLayout(this);
    if (dialect == Dialect::Carvera) {
        AppSettings settings;
        m_storedTlo = new QCheckBox(
            tr("After a manual change, set the tool's stored TLO instead of probing, when it is within the "
               "stale limit (%1 d)")
                .arg(m_sources.staleDays),
            this);
        m_storedTlo->setObjectName(u"prepareStoredTloCheck"_s);
        m_storedTlo->setChecked(settings.prepareUsesStoredTlo());
        m_breakTest = new QCheckBox(tr("Break-test each tool after its last cut, with the tolerance"), this);
        m_breakTest->setObjectName(u"prepareBreakTestCheck"_s);
        m_breakTest->setChecked(settings.prepareBreakTests());
        m_tolerance = new QDoubleSpinBox(this);
        m_tolerance->setObjectName(u"prepareToleranceSpin"_s);
        m_tolerance->setAccessibleName(tr("Break-test tolerance"));
        m_tolerance->setRange(Limits::kMinBreakTolerance, 5.0);
        m_tolerance->setDecimals(3);
        m_tolerance->setSingleStep(0.01);
        m_tolerance->setSuffix(u" mm"_s);
        m_tolerance->setValue(settings.breakTestTolerance());
        auto *breakRow = new QHBoxLayout;
        breakRow->addWidget(m_breakTest);
        breakRow->addWidget(m_tolerance);
        breakRow->addStretch(1);
        layout->addWidget(m_storedTlo);
        layout->addLayout(breakRow);
        for (QCheckBox *box : { m_storedTlo, m_breakTest })
            connect(box, &QCheckBox::toggled, this, &JobPrepareDialog::preview);
        connect(m_breakTest, &QCheckBox::toggled, m_tolerance, &QWidget::setEnabled);
        connect(m_tolerance, &QDoubleSpinBox::editingFinished, this, &JobPrepareDialog::preview);
    } else {
        layout->addWidget(
            new QLabel(tr("%1: the missing G43 after each tool change is inserted, and nothing else.")
                           .arg(dialectInfo(dialect).name),
                this));
    }
    m_progress->setObjectName(u"prepareProgress"_s);
    m_progress->setRange(0, 1000);
    m_progress->setTextVisible(false);
    m_cancel->setObjectName(u"prepareCancelButton"_s);
    m_save->setObjectName(u"prepareSaveButton"_s);
    m_status->setObjectName(u"prepareStatusLabel"_s);
    m_status->setWordWrap(true);
    m_status->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_preview->setObjectName(u"preparePreview"_s);
    m_preview->setAccessibleName(tr("The original and the prepared program, side by side"));
    m_preview->setHorizontalHeaderLabels({ tr("Line"), tr("Original"), tr("Line"), tr("Prepared") });
    m_preview->verticalHeader()->hide();
    m_preview->verticalHeader()->setDefaultSectionSize(m_preview->fontMetrics().height() + 6);
    m_preview->setTabKeyNavigation(false);
    m_preview->setWordWrap(false);
    m_preview->setEditTriggers(QAbstractItemView::NoEditTriggers);
    useMonospace(m_preview);
    auto *running = new QHBoxLayout;
    running->addWidget(m_progress, 1);
    running->addWidget(m_cancel);
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_save, QDialogButtonBox::AcceptRole);
    layout->addLayout(running);
    layout->addWidget(m_preview, 1);
    layout->addWidget(m_status);
    layout->addWidget(buttons);
    resize(1000, 620);
    connect(buttons, &QDialogButtonBox::rejected, this, &JobPrepareDialog::reject);
    connect(m_save, &QPushButton::clicked, this, &JobPrepareDialog::save);
    connect(m_cancel, &QPushButton::clicked, m_task, &BackgroundTask::cancel);
    connect(m_task, &BackgroundTask::progressed, m_progress, &QProgressBar::setValue);
    connect(m_task, &BackgroundTask::finished, this, &JobPrepareDialog::finished);
    setRunning(false);
    preview();
}

JobPrepareDialog::~JobPrepareDialog() = default;

PrepareOptions JobPrepareDialog::options() const
{
    PrepareOptions o;
    o.dialect = m_dialect;
    o.staleDays = m_sources.staleDays;
    o.zFloor = m_zFloor;
    o.machineReferenceMz = m_sources.machineReferenceMz;
    if (m_dialect == Dialect::Carvera) {
        o.useStoredTlo = m_storedTlo->isChecked();
        o.breakTest = m_breakTest->isChecked();
        o.tolerance = m_tolerance->value();
        o.rack = m_rack;
    }
    return o;
}

void JobPrepareDialog::preview()
{
    run({});
}

void JobPrepareDialog::saveTo(const QString &output)
{
    run(output);
}

bool JobPrepareDialog::isRunning() const
{
    return m_task->isRunning();
}

void JobPrepareDialog::run(const QString &output)
{
    if (m_task->isRunning())
        return;
    if (m_dialect == Dialect::Carvera) {
        AppSettings settings;
        settings.setPrepareUsesStoredTlo(m_storedTlo->isChecked());
        settings.setPrepareBreakTests(m_breakTest->isChecked());
    }
    m_output = output;
    auto result = std::make_shared<Result<PrepareSummary>>(Error {});
    m_result = result;
    setRunning(true);
    m_status->setText(output.isEmpty() ? tr("Preparing the preview…") : tr("Writing %1…").arg(output));
    m_task->start([result, path = m_programPath, sources = m_sources, o = options(), output](
                      const BackgroundTask::Progress &progress) {
        PrepareGuards guards;
        guards.preview = output.isEmpty();
        guards.protectedFiles = { sources.tablePath };
        guards.moreFacts = [&sources](QHash<int, ToolFacts> &facts, const QList<int> &tools) {
            return addHistoryFacts(sources, facts, tools);
        };
        *result = prepareJobFile(path, sources.table, o, output, progress, guards);
    });
}

void JobPrepareDialog::finished(bool cancelled)
{
    setRunning(false);
    const Result<PrepareSummary> &result = *m_result;
    if (!result && !m_output.isEmpty() && m_summary) {
        // A save that failed leaves the preview as it was: only the file was refused.
        m_status->setText(cancelled ? tr("Cancelled: nothing was written.")
                                    : tr("Not saved: %1").arg(result.error().text()));
        setRunning(false);
        Q_EMIT done();
        return;
    }
    if (!result) {
        m_summary.reset();
        m_preview->setRowCount(0);
        m_status->setText(cancelled ? tr("Cancelled: nothing was written.")
                                    : tr("The program cannot be prepared: %1").arg(result.error().text()));
        m_save->setEnabled(false);
        Q_EMIT done();
        return;
    }
    m_summary = result.value();
    showPreview();
    if (!m_output.isEmpty()) {
        m_saved = m_output;
        m_status->setText(
            m_status->text() + u' ' + tr("Written to %1.").arg(QDir::toNativeSeparators(m_output)));
    }
    Q_EMIT done();
}

void JobPrepareDialog::showPreview()
{
    const PrepareSummary &s = *m_summary;
    const QColor inserted(0x43, 0xa0, 0x47, 90);
    const QColor changed(0xe6, 0x7e, 0x00, 90);
    m_preview->setRowCount(0);
    int lastPrepared = 0;
    for (const PrepareHunk &hunk : s.hunks) {
        // "⋯" between two pieces only where lines were left out between them.
        if (!hunk.isEmpty() && hunk.front().preparedLine != lastPrepared + 1) {
            m_preview->insertRow(m_preview->rowCount());
            m_preview->setItem(m_preview->rowCount() - 1, OriginalColumn, cell(u"⋯"_s));
        }
        for (const PrepareRow &row : hunk) {
            const int r = m_preview->rowCount();
            m_preview->insertRow(r);
            const QColor mark = row.originalLine == 0 ? inserted
                : row.original != row.prepared        ? changed
                                                      : QColor();
            if (row.originalLine > 0) {
                m_preview->setItem(r, OriginalLineColumn, cell(QString::number(row.originalLine)));
                m_preview->setItem(
                    r, OriginalColumn, cell(row.original, row.original != row.prepared ? changed : QColor()));
            }
            m_preview->setItem(r, PreparedLineColumn, cell(QString::number(row.preparedLine), mark));
            m_preview->setItem(r, PreparedColumn, cell(row.prepared, mark));
            lastPrepared = row.preparedLine;
        }
    }
    m_preview->resizeColumnsToContents();
    QString text = s.inserted + s.changed == 0
        ? tr("Nothing to change: the program already does what these options ask.")
        : tr("Lines inserted: %1, changed: %2. Cutting moves checked against the original: %3; each reaches "
             "the same work position with its tool's own offset.")
              .arg(s.inserted)
              .arg(s.changed)
              .arg(s.cuttingMoves);
    if (s.moreHunks > 0)
        text += u' '
            + tr("The preview shows the first %1 changes; the other %2 are not shown.")
                  .arg(s.hunks.size())
                  .arg(s.moreHunks);
    if (!s.notes.isEmpty())
        text += u"\n"_s + s.notes.join(u'\n');
    m_status->setText(text);
    m_save->setEnabled(s.inserted + s.changed > 0);
}

void JobPrepareDialog::save()
{
    const QString path = QFileDialog::getSaveFileName(this, tr("Save Prepared Program"),
        preparedName(m_programPath), tr("G-code programs (*.nc *.gcode *.ngc *.tap *.cnc);;All files (*)"));
    if (!path.isEmpty())
        saveTo(path);
}

void JobPrepareDialog::setRunning(bool running)
{
    m_progress->setVisible(running);
    m_cancel->setVisible(running);
    m_save->setEnabled(!running && m_summary && m_summary->inserted + m_summary->changed > 0);
    for (QWidget *w : std::initializer_list<QWidget *> { m_storedTlo, m_breakTest, m_tolerance }) {
        if (w)
            w->setEnabled(!running && (w != m_tolerance || m_breakTest->isChecked()));
    }
}

void JobPrepareDialog::reject()
{
    // Closing stops the work; the dialog goes once it has.
    m_task->stopThen(this, [this] { QDialog::reject(); });
}

} // namespace Toffee
