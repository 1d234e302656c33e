// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/historydock.h"

#include <algorithm>

#include <QAbstractTableModel>
#include <QAreaSeries>
#include <QChart>
#include <QChartView>
#include <QClipboard>
#include <QDateTimeAxis>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineSeries>
#include <QLocale>
#include <QPainter>
#include <QPushButton>
#include <QSplitter>
#include <QTableView>
#include <QTimer>
#include <QVBoxLayout>
#include <QValueAxis>

#include "model/formats/fileio.h"
#include "model/library/historyrecorder.h"
#include "model/numberformat.h"
#include "ui/appearance.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

enum class MarkerShape { Circle, Triangle, Square };

// Points drawn as light markers on an invisible line: one chart item for the whole series, so ten thousand
// measurements draw in milliseconds (a QScatterSeries makes an item per point).
QLineSeries *markers(const QString &name, MarkerShape shape, const QColor &color, int size)
{
    QImage image(size, size, QImage::Format_ARGB32_Premultiplied);
    image.fill(Qt::transparent);
    QPainter painter(&image);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(QPen(color.darker(140), 1));
    painter.setBrush(color);
    const QRectF box(0.5, 0.5, size - 1.0, size - 1.0);
    if (shape == MarkerShape::Circle) {
        painter.drawEllipse(box);
    } else if (shape == MarkerShape::Square) {
        painter.drawRect(box.adjusted(1, 1, -1, -1));
    } else {
        painter.drawPolygon(
            QPolygonF({ QPointF(box.center().x(), box.top()), box.bottomRight(), box.bottomLeft() }));
    }
    painter.end();
    auto *series = new QLineSeries;
    series->setName(name);
    series->setPen(Qt::NoPen);
    series->setColor(color);
    series->setLightMarker(image);
    series->setMarkerSize(size);
    return series;
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
        return HistoryDock::tr("imported");
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
    enum Column { Time, Kind, Tlo, Reference, Current, Tolerance, OldTlo, NewTlo, Verdict, ColumnCount };

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
            HistoryDock::tr("Old TLO"), HistoryDock::tr("New TLO"), HistoryDock::tr("Result") };
        return section >= 0 && section < ColumnCount ? names[section] : QVariant();
    }
    QVariant data(const QModelIndex &index, int role) const override
    {
        if (!index.isValid() || !m_events)
            return {};
        const HistoryEvent &e = m_events->at(m_events->size() - 1 - index.row()); // newest first
        if (role == Qt::TextAlignmentRole)
            return index.column() >= Tlo && index.column() <= NewTlo
                ? QVariant::fromValue(Qt::AlignRight | Qt::AlignVCenter)
                : QVariant();
        if (role == Qt::ForegroundRole && index.column() == Verdict && e.failed.value_or(false))
            return m_alarm;
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
    showTool(-1, {}, m_tolerance);
}

QPushButton *HistoryDock::exportButton() const
{
    return m_export;
}

QChart *HistoryDock::chart() const
{
    return m_view ? m_view->chart() : nullptr;
}

void HistoryDock::showEvent(QShowEvent *event)
{
    QDockWidget::showEvent(event);
    if (m_stale)
        QTimer::singleShot(0, this, &HistoryDock::reload);
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
    // Drawn when seen: a panel behind the console's tab builds no chart (Qt Charts is slow to start).
    if (!isVisible()) {
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
    m_copy->setEnabled(m_tool >= 0);
}

void HistoryDock::fillChart(const std::optional<WearTrend> &trend, const QList<TrendPoint> &points)
{
    auto *chart = new QChart;
    chart->setMargins(QMargins(4, 4, 4, 4));
    chart->legend()->setAlignment(Qt::AlignBottom);
    const QColor alarm = alarmColor(palette());
    const QColor text = palette().color(QPalette::Text);
    chart->setBackgroundBrush(palette().brush(QPalette::Base));
    // The axis labels in the user's decimal mark ("-33,400" in German), like every other number in the
    // window.
    chart->setLocalizeNumbers(true);
    chart->setLocale(QLocale());
    chart->setTitleBrush(text);
    chart->legend()->setLabelColor(text);
    auto *probes = markers(tr("Probes"), MarkerShape::Circle, palette().color(QPalette::Highlight), 8);
    auto *passed = markers(tr("Break test passed"), MarkerShape::Triangle, QColor(0x26, 0xa2, 0x69), 11);
    auto *failed = markers(tr("Break test failed"), MarkerShape::Triangle, alarm, 13);
    auto *manual = markers(tr("Set by hand"), MarkerShape::Square, QColor(0x98, 0x6a, 0x44), 9);
    QList<QPointF> probeTimes;
    for (const HistoryEvent &e : m_events) {
        const qreal t = qreal(e.at.toMSecsSinceEpoch());
        if (e.kind == EventKind::BreakTest && (e.newTlo || e.tlo))
            (e.failed.value_or(false) ? failed : passed)->append(t, e.newTlo.value_or(*e.tlo));
        else if (e.kind == EventKind::Probe && e.tlo)
            probeTimes.append({ t, *e.tlo });
        else if (e.tlo)
            manual->append(t, *e.tlo);
    }
    probes->replace(probeTimes);
    QList<QAbstractSeries *> all { probes, passed, failed, manual };
    if (trend && trend->points >= 2 && probeTimes.size() == points.size()) {
        // The trend at each probe's place in the tool's life, drawn at the probe's time, with ± the
        // tolerance.
        auto *line = new QLineSeries;
        auto *upper = new QLineSeries;
        auto *lower = new QLineSeries;
        line->setName(tr("Wear trend"));
        for (qsizetype i = 0; i < points.size(); ++i) {
            const qreal y = trend->predict(points.at(i).x);
            line->append(probeTimes.at(i).x(), y);
            upper->append(probeTimes.at(i).x(), y + m_tolerance);
            lower->append(probeTimes.at(i).x(), y - m_tolerance);
        }
        auto *band = new QAreaSeries(upper, lower);
        band->setName(tr("± %1 mm").arg(formatNumber(m_tolerance, NumberFormat::upTo(3).inLocale())));
        QColor fill = palette().color(QPalette::Highlight);
        fill.setAlpha(40);
        band->setBrush(fill);
        band->setPen(Qt::NoPen);
        line->setPen(QPen(palette().color(QPalette::Highlight), 1.5, Qt::DashLine));
        all.prepend(line);
        all.prepend(band);
    }
    for (QAbstractSeries *s : all)
        chart->addSeries(s);
    if (m_events.isEmpty())
        chart->setTitle(m_tool < 0 ? QString() : tr("No measurements of T%1 yet").arg(m_tool));
    auto *time = new QDateTimeAxis;
    time->setFormat(QLocale().dateFormat(QLocale::ShortFormat));
    time->setLabelsBrush(text);
    auto *tlo = new QValueAxis;
    tlo->setTitleText(tr("TLO (mm)"));
    tlo->setTitleBrush(text);
    tlo->setLabelsBrush(text);
    tlo->setLabelFormat(u"%.3f"_s);
    chart->addAxis(time, Qt::AlignBottom);
    chart->addAxis(tlo, Qt::AlignLeft);
    // Set once the chart's theme has dressed the axes: grid lines that stay in the background on the light
    // and the dark palette alike.
    const QColor grid = palette().color(QPalette::Text).lightness() > 128 ? QColor(0x55, 0x55, 0x55)
                                                                          : QColor(0xd0, 0xd0, 0xd0);
    for (QAbstractAxis *axis : { static_cast<QAbstractAxis *>(time), static_cast<QAbstractAxis *>(tlo) }) {
        axis->setGridLineColor(grid);
        axis->setLinePenColor(grid);
        axis->setLabelsBrush(palette().color(QPalette::Text));
    }
    qreal x0 = std::numeric_limits<qreal>::max();
    qreal x1 = std::numeric_limits<qreal>::lowest();
    qreal y0 = x0;
    qreal y1 = x1;
    for (QAbstractSeries *s : all) {
        s->attachAxis(time);
        s->attachAxis(tlo);
        if (auto *xy = qobject_cast<QXYSeries *>(s)) {
            for (const QPointF &p : xy->points()) {
                x0 = std::min(x0, p.x());
                x1 = std::max(x1, p.x());
                y0 = std::min(y0, p.y());
                y1 = std::max(y1, p.y());
            }
        }
    }
    if (x0 > x1) { // nothing to draw: today, around zero
        x0 = qreal(QDateTime::currentMSecsSinceEpoch());
        x1 = x0;
        y0 = y1 = 0.0;
    }
    const qreal hour = 3600.0 * 1000.0;
    const qreal xPad = std::max(hour, (x1 - x0) * 0.03);
    const qreal yPad = std::max(0.05, (y1 - y0) * 0.1);
    time->setRange(
        QDateTime::fromMSecsSinceEpoch(qint64(x0 - xPad)), QDateTime::fromMSecsSinceEpoch(qint64(x1 + xPad)));
    tlo->setRange(y0 - yPad, y1 + yPad);
    tlo->applyNiceNumbers(); // ticks at round millimetres, not at the data's own edges
    // Within a few days the dates repeat: show the times. With nothing to draw, no axes at all.
    if (x1 + xPad - (x0 - xPad) < 3 * 24 * hour)
        time->setFormat(QLocale().timeFormat(QLocale::ShortFormat));
    time->setVisible(!m_events.isEmpty());
    tlo->setVisible(!m_events.isEmpty());
    if (!m_view) {
        // Made when first seen: a chart view costs the window's first frame several milliseconds.
        m_view = new QChartView(this);
        m_view->setObjectName(u"historyChart"_s);
        m_view->setRenderHint(QPainter::Antialiasing);
        m_view->setMinimumHeight(180);
        m_view->setAccessibleName(tr("TLO over time"));
        m_split->insertWidget(0, m_view);
        m_split->setStretchFactor(0, 3);
        m_split->setStretchFactor(1, 2);
    }
    QChart *old = m_view->chart();
    m_view->setChart(chart);
    delete old;
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
