// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/history/historydock.h"

#include <algorithm>

#include <QAbstractTableModel>
#include <QClipboard>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLocale>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>

#include "model/formats/fileio.h"
#include "model/library/historyrecorder.h"
#include "model/modules.h"
#include "model/numberformat.h"
#include "ui/common/appearance.h"
#include "ui/history/chart/historychart.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

constexpr int kChartHeight = 180; // the chart's least height, and its place's before it is made

// The chart module's two functions, resolved each time a chart is drawn (microseconds once it is loaded), so
// a module put back is found without a restart.
struct ChartModule
{
    MakeHistoryChartView make = nullptr;
    FillHistoryChart fill = nullptr;
};

Result<ChartModule> chartModule()
{
    const QLatin1StringView file(kHistoryChartModule);
    const auto make = resolveInModule(file, kMakeHistoryChartViewSymbol);
    const auto fill = make ? resolveInModule(file, kFillHistoryChartSymbol) : make;
    if (!fill) {
        const Error &e = fill.error();
        return Error { e.code == kModuleMissing
                ? HistoryDock::tr("The chart cannot be drawn: Toffee's chart module %1 is missing. Reinstall "
                                  "Toffee; the measurements are in the table below.")
                      .arg(e.file)
                : HistoryDock::tr(
                    "The chart cannot be drawn: Toffee's chart module %1 cannot be loaded (%2). "
                    "Reinstall Toffee; the measurements are in the table below.")
                      .arg(e.file, e.message) };
    }
    return ChartModule { reinterpret_cast<MakeHistoryChartView>(make.value()),
        reinterpret_cast<FillHistoryChart>(fill.value()) };
}

QString kindText(EventKind kind)
{
    switch (kind) {
    case EventKind::Probe:
        return HistoryDock::tr("probe");
    case EventKind::BreakTest:
        return HistoryDock::tr("break test");
    case EventKind::ManualSet:
        return HistoryDock::tr("set by hand");
    case EventKind::Restore:
        return HistoryDock::tr("restored");
    case EventKind::Import:
        return HistoryDock::tr("read in");
    case EventKind::NewCutter:
        return HistoryDock::tr("new cutter (old one ended)");
    }
    return {};
}

QString lengthCell(std::optional<double> v)
{
    return v ? millimetres(*v, false) : QString();
}

} // namespace

// The measurements, newest first, formatted only when a view asks: ten thousand rows cost no items.
class HistoryTableModel final : public QAbstractTableModel
{
public:
    enum Column {
        Time,
        Kind,
        Tlo,
        Reference,
        Current,
        Tolerance,
        OldTlo,
        NewTlo,
        Spread,
        Verdict,
        ColumnCount
    };

    explicit HistoryTableModel(QObject *parent)
        : QAbstractTableModel(parent)
    { }
    void setEvents(const QList<HistoryEvent> *events, const QColor &alarm)
    {
        beginResetModel();
        m_events = events;
        m_alarm = alarm;
        endResetModel();
    }
    int rowCount(const QModelIndex &parent = {}) const override
    {
        return parent.isValid() || !m_events ? 0 : int(m_events->size());
    }
    int columnCount(const QModelIndex &parent = {}) const override
    {
        return parent.isValid() ? 0 : ColumnCount;
    }
    QVariant headerData(int section, Qt::Orientation orientation, int role) const override
    {
        if (orientation != Qt::Horizontal || role != Qt::DisplayRole)
            return {};
        const QString names[] = { HistoryDock::tr("Time"), HistoryDock::tr("Kind"), HistoryDock::tr("TLO"),
            HistoryDock::tr("Reference Z"), HistoryDock::tr("Current Z"), HistoryDock::tr("Tolerance"),
            HistoryDock::tr("Old TLO"), HistoryDock::tr("New TLO"), HistoryDock::tr("Spread"),
            HistoryDock::tr("Result") };
        return section >= 0 && section < ColumnCount ? names[section] : QVariant();
    }
    QVariant data(const QModelIndex &index, int role) const override
    {
        if (!index.isValid() || !m_events)
            return {};
        const HistoryEvent &e = m_events->at(m_events->size() - 1 - index.row()); // newest first
        if (role == Qt::TextAlignmentRole)
            return index.column() >= Tlo && index.column() <= Spread
                ? QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter)
                : QVariant();
        if (role == Qt::ForegroundRole && index.column() == Verdict && e.failed.value_or(false))
            return m_alarm;
        if (role == Qt::ToolTipRole && index.column() == Spread && e.spread()) {
            QStringList each;
            for (double z : e.touches)
                each << formatNumber(z, NumberFormat::fixed(3).inLocale());
            return HistoryDock::tr(
                "%1 touches, at machine Z %2 mm: the TLO is the highest's (the longest edge)")
                .arg(e.touches.size())
                .arg(each.join(u", "_s));
        }
        if (role != Qt::DisplayRole)
            return {};
        switch (index.column()) {
        case Time:
            return QLocale().toString(e.at.toLocalTime(), QLocale::ShortFormat);
        case Kind:
            return kindText(e.kind);
        case Tlo:
            return lengthCell(e.tlo);
        case Reference:
            return lengthCell(e.referenceMz);
        case Current:
            return lengthCell(e.currentMz);
        case Tolerance:
            return lengthCell(e.tolerance);
        case OldTlo:
            return lengthCell(e.oldTlo);
        case NewTlo:
            return lengthCell(e.newTlo);
        case Spread:
            return lengthCell(e.spread());
        case Verdict:
            return !e.failed ? QString() : *e.failed ? HistoryDock::tr("BROKEN?") : HistoryDock::tr("passed");
        default:
            return {};
        }
    }

private:
    const QList<HistoryEvent> *m_events = nullptr;
    QColor m_alarm;
};

HistoryDock::HistoryDock(HistoryRecorder *recorder, QWidget *parent)
    : QDockWidget(tr("History"), parent)
    , m_recorder(recorder)
    , m_title(new QLabel(this))
    , m_table(new QTableView(this))
    , m_model(new HistoryTableModel(this))
    , m_export(new QPushButton(tr("Export CSV…"), this))
    , m_copy(new QPushButton(tr("Copy Chart"), this))
{
    setObjectName(u"historyDock"_s);
    m_title->setObjectName(u"historyTitle"_s);
    m_table->setObjectName(u"historyTable"_s);
    m_table->setModel(m_model);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setResizeContentsPrecision(200);
    m_table->setAccessibleName(tr("Measurements"));
    m_export->setObjectName(u"historyExportButton"_s);
    m_copy->setObjectName(u"historyCopyButton"_s);
    connect(m_copy, &QPushButton::clicked, this, &HistoryDock::copyChart);
    // Export asks the window for a file name: it is wired where the dialogs live.

    m_split = new QSplitter(Qt::Vertical, this);
    auto *split = m_split;
    // The chart's place, as tall as the chart will be: the panel keeps its size when the chart is made, the
    // first time the panel is seen, and says here why when it cannot be.
    m_chartPlace = new QLabel(this);
    m_chartPlace->setObjectName(u"historyChartPlace"_s);
    m_chartPlace->setMinimumHeight(kChartHeight);
    m_chartPlace->setWordWrap(true);
    m_chartPlace->setTextFormat(Qt::PlainText);
    m_chartPlace->setAlignment(Qt::AlignCenter);
    m_chartPlace->setMargin(12);
    split->addWidget(m_chartPlace);
    split->addWidget(m_table);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_title, 1);
    buttons->addWidget(m_export);
    buttons->addWidget(m_copy);
    auto *body = new QWidget(this);
    auto *layout = new QVBoxLayout(body);
    layout->setContentsMargins(4, 4, 4, 4);
    layout->addLayout(buttons);
    layout->addWidget(split, 1);
    setWidget(body);

    connect(m_recorder, &HistoryRecorder::recorded, this, [this](const QList<HistoryEvent> &written) {
        if (std::any_of(written.cbegin(), written.cend(),
                [this](const HistoryEvent &e) { return e.tool == m_tool && e.machine == m_machine; }))
            reload();
    });
    // Seen or not, as Qt tells it: a panel behind another's tab is "visible" to isVisible(), only moved out
    // of sight, so that isVisible() had the chart built at every start.
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool seen) {
        m_seen = seen;
        if (seen && m_stale)
            QTimer::singleShot(0, this, &HistoryDock::reload);
    });
    showTool(-1, {}, m_tolerance);
}

QPushButton *HistoryDock::exportButton() const
{
    return m_export;
}

QWidget *HistoryDock::chartView() const
{
    return m_view;
}

void HistoryDock::showTool(int tool, const QString &machine, double tolerance)
{
    m_tool = tool;
    m_machine = machine;
    m_tolerance = tolerance;
    reload();
}

void HistoryDock::reload()
{
    // Drawn when seen: a panel behind the console's tab builds no chart (Qt Charts is slow to start, and its
    // module is loaded then).
    if (!m_seen) {
        m_stale = true;
        return;
    }
    m_stale = false;
    m_events.clear();
    QList<ToolUse> uses;
    if (m_tool >= 0 && m_recorder->library()) {
        const HistoryQuery query { m_machine, m_tool, {}, 0 };
        if (auto read = m_recorder->library()->history(query))
            m_events = read.value();
        if (auto read = m_recorder->library()->uses(m_machine, m_tool))
            uses = read.value();
    }
    if (m_tool < 0)
        m_title->setText(tr("Select one tool to see its history."));
    else if (!m_recorder->library())
        m_title->setText(tr("T%1: the history library is not open.").arg(m_tool));
    else
        m_title->setText(m_events.size() == 1
                ? tr("T%1 on %2: 1 measurement").arg(m_tool).arg(m_machine)
                : tr("T%1 on %2: %3 measurements").arg(m_tool).arg(m_machine).arg(m_events.size()));
    bool overCutting = false;
    const QList<TrendPoint> points = WearTrend::pointsOf(m_events, uses, &overCutting);
    fillChart(WearTrend::fit(points), points);
    fillTable();
    m_export->setEnabled(!m_events.isEmpty());
    m_copy->setEnabled(m_tool >= 0 && m_view);
}

void HistoryDock::fillChart(const std::optional<WearTrend> &trend, const QList<TrendPoint> &points)
{
    const auto module = chartModule();
    if (!module) {
        if (m_chartPlace)
            m_chartPlace->setText(module.error().message);
        return;
    }
    if (!m_view) {
        // Made when first seen: a chart view costs the window's first frame several milliseconds.
        m_view = module.value().make(this);
        m_view->setObjectName(u"historyChart"_s);
        m_view->setMinimumHeight(kChartHeight);
        m_view->setAccessibleName(tr("TLO over time"));
        delete m_split->replaceWidget(0, m_view);
        m_chartPlace = nullptr;
    }
    HistoryChartInput input { &m_events, trend, points, m_tolerance, palette(), alarmColor(palette()),
        { tr("Probes"), tr("Break test passed"), tr("Break test failed"), tr("Set by hand"), tr("Old cutter"),
            tr("Wear trend"), tr("Each edge"),
            tr("± %1 mm").arg(formatNumber(m_tolerance, NumberFormat::upTo(3).inLocale())),
            m_events.isEmpty() && m_tool >= 0 ? tr("No measurements of T%1 yet").arg(m_tool) : QString(),
            tr("TLO (mm)") } };
    module.value().fill(m_view, input);
}

void HistoryDock::fillTable()
{
    m_model->setEvents(&m_events, alarmColor(palette()));
    m_table->resizeColumnsToContents(); // from the first rows: the header's precision is bounded
}

QByteArray HistoryDock::csv() const
{
    return eventsAsCsv(m_events);
}

Result<void> HistoryDock::exportCsv(const QString &path) const
{
    const QByteArray text = csv();
    return writeFileAtomically(path, [&text](const FileSink &sink) { return sink(text); });
}

void HistoryDock::copyChart()
{
    if (m_view)
        QGuiApplication::clipboard()->setImage(m_view->grab().toImage());
}

} // namespace Toffee
