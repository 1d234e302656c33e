// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/job/jobcheckdialog.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QProgressBar>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QTextBlock>
#include <QVBoxLayout>

#include "model/clock.h"
#include "model/job/jobcheck.h"
#include "model/job/programexcerpt.h"
#include "model/numberformat.h"
#include "model/timetext.h"
#include "ui/common/appearance.h"
#include "ui/common/appsettings.h"
#include "ui/common/backgroundtask.h"
#include "ui/job/jobpreparedialog.h"
#include "ui/job/jobreportmodels.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr int kExcerptContext = 8;

QTableView *reportView(
    QAbstractItemModel *model, const QString &name, const QString &accessible, QWidget *parent)
{
    auto *view = new QTableView(parent);
    view->setObjectName(name);
    view->setAccessibleName(accessible);
    view->setModel(model);
    view->setSelectionBehavior(QAbstractItemView::SelectRows);
    view->setSelectionMode(QAbstractItemView::SingleSelection);
    view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    view->verticalHeader()->hide();
    view->horizontalHeader()->setStretchLastSection(true);
    view->setWordWrap(false);
    view->setTabKeyNavigation(false); // Tab leaves the table for the next control; the arrows move in it
    view->verticalHeader()->setDefaultSectionSize(view->fontMetrics().height() + 8);
    return view;
}

// A table with its title above it, the title's shortcut focusing it.
QWidget *titled(const QString &title, QWidget *content, QWidget *parent)
{
    auto *box = new QWidget(parent);
    auto *label = new QLabel(title, box);
    label->setBuddy(content);
    QFont bold = label->font();
    bold.setBold(true);
    label->setFont(bold);
    auto *layout = new QVBoxLayout(box);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(2);
    layout->addWidget(label);
    layout->addWidget(content, 1);
    return box;
}

// Everything a check needs, copied for its thread: it shares nothing with the window while it runs.
struct CheckInput
{
    QString path;
    JobCheckSetup setup;
    JobSources sources;
};

Result<JobReport> runCheck(const CheckInput &in, const BackgroundTask::Progress &progress)
{
    const JobFactSource facts = [&in](QHash<int, ToolFacts> &known, const QList<int> &tools) {
        return addHistoryFacts(in.sources, known, tools);
    };
    return checkJobFile(in.path, in.setup, facts, progress);
}

} // namespace

JobCheckDialog::JobCheckDialog(Sources sources, QWidget *parent)
    : QDialog(parent)
    , m_sources(std::move(sources))
    , m_task(new BackgroundTask(this))
    , m_toolsModel(new JobToolsModel(this))
    , m_findingsModel(new JobFindingsModel(this))
    , m_dialect(new QComboBox(this))
    , m_useFloor(new QCheckBox(tr("Z &floor:"), this))
    , m_floor(new QDoubleSpinBox(this))
    , m_rack(new QLineEdit(this))
    , m_program(new QLabel(this))
    , m_progress(new QProgressBar(this))
    , m_cancel(new QPushButton(tr("Cancel"), this))
    , m_again(new QPushButton(tr("Check &Again"), this))
    , m_prepare(new QPushButton(tr("&Prepare…"), this))
    , m_summary(new QLabel(this))
    , m_tools(reportView(m_toolsModel, u"jobToolsView"_s, tr("Tools in order of use"), this))
    , m_findings(reportView(m_findingsModel, u"jobFindingsView"_s, tr("Findings"), this))
    , m_excerpt(new QPlainTextEdit(this))
{
    setObjectName(u"jobCheckDialog"_s);
    setWindowTitle(tr("Check Job"));
    buildControls();
    connect(m_task, &BackgroundTask::progressed, m_progress, &QProgressBar::setValue);
    connect(m_task, &BackgroundTask::finished, this, &JobCheckDialog::finished);
    connect(m_cancel, &QPushButton::clicked, this, &JobCheckDialog::cancel);
    connect(m_again, &QPushButton::clicked, this, [this] { check(m_path); });
    connect(m_prepare, &QPushButton::clicked, this, &JobCheckDialog::prepare);
    connect(m_findings, &QTableView::activated, this,
        [this](const QModelIndex &index) { showLine(index.data(JobFindingsModel::LineRole).toInt()); });
    setRunning(false);
    m_tools->horizontalHeader()->setStretchLastSection(false);
    // A finding is read whole, in any language: its message wraps within the dialog's width, the row as tall
    // as it needs, never cut off at the edge ("… wartet auf den …").
    m_findings->setWordWrap(true);
    m_findings->horizontalHeader()->setSectionResizeMode(
        JobFindingsModel::MessageColumn, QHeaderView::Stretch);
    m_findings->verticalHeader()->setSectionResizeMode(QHeaderView::ResizeToContents);
    resize(900, 640);
}

JobCheckDialog::~JobCheckDialog() = default;

void JobCheckDialog::setSources(Sources sources)
{
    m_sources = std::move(sources);
    if (m_sources.machineDialect)
        m_dialect->setCurrentIndex(
            std::max(0, m_dialect->findData(dialectInfo(*m_sources.machineDialect).key)));
}

void JobCheckDialog::buildControls()
{
    m_dialect->setObjectName(u"jobDialectCombo"_s);
    m_dialect->setAccessibleName(tr("Controller"));
    for (const DialectInfo &info : dialects())
        m_dialect->addItem(info.name, info.key);
    m_dialect->setCurrentIndex(std::max(0,
        m_dialect->findData(m_sources.machineDialect ? dialectInfo(*m_sources.machineDialect).key
                                                     : AppSettings().jobDialect())));
    m_useFloor->setObjectName(u"jobFloorCheck"_s);
    m_floor->setObjectName(u"jobFloorSpin"_s);
    m_floor->setAccessibleName(tr("Lowest work Z a feed move may reach"));
    m_floor->setRange(-kMaxMachineMillimetres, kMaxMachineMillimetres);
    m_floor->setDecimals(3);
    m_floor->setSuffix(u" mm"_s);
    const std::optional<double> floor = AppSettings().jobZFloor();
    m_useFloor->setChecked(floor.has_value());
    m_floor->setValue(floor.value_or(-20.0));
    m_floor->setEnabled(floor.has_value());
    connect(m_useFloor, &QCheckBox::toggled, m_floor, &QWidget::setEnabled);
    m_rack->setObjectName(u"jobRackEdit"_s);
    m_rack->setAccessibleName(tr("The tools the Carvera's rack holds"));
    m_rack->setToolTip(
        tr("The tools the rack holds: 1-6 on a Carvera C1, none on a machine without one, or a "
           "list such as 1-4,8. Every other tool is a manual change."));
    m_rack->setText(AppSettings().jobRack());
    m_rack->setMaximumWidth(120);
    m_rack->setPlaceholderText(tr("1-6, or none"));
    // Another controller, floor or rack is another check: it runs again, so that what is shown is what they
    // find.
    connect(m_dialect, &QComboBox::currentIndexChanged, this, &JobCheckDialog::optionsChanged);
    connect(m_useFloor, &QCheckBox::toggled, this, &JobCheckDialog::optionsChanged);
    connect(m_floor, &QDoubleSpinBox::editingFinished, this, &JobCheckDialog::optionsChanged);
    connect(m_rack, &QLineEdit::editingFinished, this, &JobCheckDialog::optionsChanged);
    m_program->setObjectName(u"jobProgramLabel"_s);
    m_program->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_progress->setObjectName(u"jobProgress"_s);
    m_progress->setAccessibleName(tr("How far the check is"));
    m_progress->setRange(0, 1000);
    m_progress->setTextVisible(false);
    m_cancel->setObjectName(u"jobCancelButton"_s);
    m_again->setObjectName(u"jobCheckAgainButton"_s);
    m_prepare->setObjectName(u"jobPrepareButton"_s);
    m_summary->setObjectName(u"jobSummaryLabel"_s);
    m_summary->setWordWrap(true);
    m_excerpt->setObjectName(u"jobExcerpt"_s);
    m_excerpt->setAccessibleName(tr("The program around the finding"));
    m_excerpt->setReadOnly(true);
    m_excerpt->setLineWrapMode(QPlainTextEdit::NoWrap);
    m_excerpt->setPlaceholderText(tr("Double-click a finding to see the program around its line."));
    useMonospace(m_excerpt);

    auto *options = new QHBoxLayout;
    options->addWidget(new QLabel(tr("Controller:"), this));
    options->addWidget(m_dialect);
    options->addSpacing(12);
    options->addWidget(m_useFloor);
    options->addWidget(m_floor);
    options->addSpacing(12);
    auto *rackLabel = new QLabel(tr("&Rack holds:"), this);
    rackLabel->setBuddy(m_rack);
    options->addWidget(rackLabel);
    options->addWidget(m_rack);
    options->addStretch(1);
    options->addWidget(m_again);
    auto *running = new QHBoxLayout;
    running->addWidget(m_progress, 1);
    running->addWidget(m_cancel);
    auto *split = new QSplitter(Qt::Vertical, this);
    split->addWidget(titled(tr("&Tools, in order of use"), m_tools, this));
    split->addWidget(titled(tr("F&indings, by line"), m_findings, this));
    split->addWidget(m_excerpt);
    split->setSizes({ 170, 260, 150 });
    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    buttons->addButton(m_prepare, QDialogButtonBox::ActionRole);
    connect(buttons, &QDialogButtonBox::rejected, this, &JobCheckDialog::reject);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_program);
    layout->addLayout(options);
    layout->addLayout(running);
    layout->addWidget(m_summary);
    layout->addWidget(split, 1);
    layout->addWidget(buttons);
}

void JobCheckDialog::check(const QString &path)
{
    if (m_task->isRunning()) {
        // The one running stops first; this one starts when it has.
        m_pending = path;
        m_task->cancel();
        return;
    }
    saveSettings();
    m_path = path;
    m_report.reset();
    m_toolsModel->setReport({}, {});
    m_findingsModel->setFindings({});
    m_excerpt->clear();
    m_program->setText(tr("Program: %1").arg(QDir::toNativeSeparators(path)));
    m_summary->setText(tr("Checking…"));
    CheckInput input { path, {}, m_sources };
    input.setup.dialect = dialectFromKey(m_dialect->currentData().toString()).value_or(Dialect::Carvera);
    input.setup.useTable(m_sources.table);
    input.setup.staleDays = m_sources.staleDays;
    input.setup.controllerTlos = m_sources.controllerTlos;
    if (m_useFloor->isChecked())
        input.setup.zFloor = m_floor->value();
    if (input.setup.dialect == Dialect::Carvera)
        input.setup.rack = rack();
    auto result = std::make_shared<Result<JobReport>>(Error {});
    m_result = result;
    setRunning(true);
    m_task->start(
        [result, input](const BackgroundTask::Progress &progress) { *result = runCheck(input, progress); });
}

void JobCheckDialog::cancel()
{
    m_task->cancel();
}

bool JobCheckDialog::isRunning() const
{
    return m_task->isRunning();
}

void JobCheckDialog::finished(bool cancelled)
{
    setRunning(false);
    if (!m_pending.isEmpty()) {
        check(std::exchange(m_pending, QString()));
        return;
    }
    const Result<JobReport> &result = *m_result;
    if (!result) {
        m_summary->setText(
            tr("The program could not be checked: %1").arg(result.error().text()).toHtmlEscaped());
        Q_EMIT checked();
        return;
    }
    m_report = result.value();
    m_report->cancelled = m_report->cancelled || cancelled;
    showReport();
    Q_EMIT checked();
}

void JobCheckDialog::showReport()
{
    const JobReport &r = *m_report;
    m_toolsModel->setReport(r, Clock::now());
    m_findingsModel->setFindings(r.findings);
    m_tools->resizeColumnsToContents();
    for (int c = 0; c < m_findingsModel->columnCount(); ++c) {
        if (c != JobFindingsModel::MessageColumn)
            m_findings->resizeColumnToContents(c);
    }
    m_findings->horizontalHeader()->setSectionResizeMode(
        JobFindingsModel::MessageColumn, QHeaderView::Stretch);
    QString text = tr("%1: %2 lines as %3; tools: %4, cutting %5, rapids %6 mm.")
                       .arg(r.program)
                       .arg(QLocale().toString(r.lines))
                       .arg(dialectInfo(r.dialect).name)
                       .arg(r.distinctTools())
                       .arg(durationText(r.cuttingSeconds), millimetres(r.rapidMm, false));
    if (r.moreTools > 0)
        text += u' '
            + tr("Only the first %1 tools are listed; the other %2 are counted, their findings summed up "
                 "one for each kind.")
                  .arg(r.tools.size())
                  .arg(r.moreTools);
    if (r.cancelled)
        text = tr("Cancelled after %1 lines: what was found so far.").arg(QLocale().toString(r.lines)) + u' '
            + text;
    m_summary->setText(text + u' ' + r.summary() + u'.');
    updatePrepare();
}

void JobCheckDialog::setRunning(bool running)
{
    m_progress->setVisible(running);
    m_cancel->setVisible(running);
    m_cancel->setEnabled(running);
    m_again->setEnabled(!running && !m_path.isEmpty());
    m_dialect->setEnabled(!running);
    m_useFloor->setEnabled(!running);
    m_floor->setEnabled(!running && m_useFloor->isChecked());
    m_rack->setEnabled(!running);
    updatePrepare();
    if (running)
        m_cancel->setFocus();
}

void JobCheckDialog::showLine(int line)
{
    const auto excerpt = readExcerpt(m_path, line, kExcerptContext);
    if (!excerpt) {
        m_excerpt->setPlainText(excerpt.error().text());
        return;
    }
    QStringList lines;
    const int width = int(QString::number(excerpt.value().firstLine + excerpt.value().lines.size()).size());
    for (qsizetype i = 0; i < excerpt.value().lines.size(); ++i) {
        const int number = excerpt.value().firstLine + int(i);
        lines << (number == line ? u"▶ "_s : u"  "_s) + QString::number(number).rightJustified(width)
                + u"  "_s + excerpt.value().lines.at(i);
    }
    m_excerpt->setPlainText(lines.join(u'\n'));
    const QTextBlock block = m_excerpt->document()->findBlockByNumber(line - excerpt.value().firstLine);
    QTextEdit::ExtraSelection mark;
    mark.cursor = QTextCursor(block);
    mark.format.setBackground(palette().highlight().color().lighter(160));
    mark.format.setProperty(QTextFormat::FullWidthSelection, true);
    m_excerpt->setExtraSelections({ mark });
    m_excerpt->setTextCursor(mark.cursor);
    m_excerpt->centerCursor();
}

void JobCheckDialog::prepare()
{
    if (!m_report)
        return;
    JobPrepareDialog dialog(m_path, m_sources, m_report->dialect,
        m_useFloor->isChecked() ? std::optional(m_floor->value()) : std::nullopt,
        rack().value_or(QList<int> {}), this);
    dialog.exec();
}

// Prepare… takes a program that ran through and has no errors, for a controller it can prepare for.
void JobCheckDialog::updatePrepare()
{
    const bool preparable = m_report && !m_report->cancelled
        && (m_report->dialect == Dialect::Carvera || usesG43(m_report->dialect));
    m_prepare->setEnabled(!m_task->isRunning() && preparable && m_report->errors() == 0);
    m_prepare->setToolTip(preparable && m_report->errors() > 0
            ? tr("The check found errors: fix them before preparing the program.")
            : QString());
}

void JobCheckDialog::optionsChanged()
{
    if (!m_path.isEmpty())
        check(m_path);
}

std::optional<QList<int>> JobCheckDialog::rack() const
{
    const auto parsed = parseRack(m_rack->text());
    return parsed ? std::optional(parsed.value()) : std::optional(carveraRack());
}

void JobCheckDialog::saveSettings()
{
    AppSettings settings;
    if (parseRack(m_rack->text()))
        settings.setJobRack(m_rack->text().trimmed());
    settings.setJobDialect(m_dialect->currentData().toString());
    settings.setJobZFloor(m_useFloor->isChecked() ? std::optional(m_floor->value()) : std::nullopt);
}

void JobCheckDialog::reject()
{
    // Closing stops the work; the dialog goes once it has.
    m_task->stopThen(this, [this] { QDialog::reject(); });
}

} // namespace Toffee
