// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/historydock.h"

#include <algorithm>

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
#include <QPushButton>
#include <QScatterSeries>
#include <QSplitter>
#include <QStandardItemModel>
#include <QTableView>
#include <QVBoxLayout>
#include <QValueAxis>

#include "model/formats/fileio.h"
#include "model/library/historyrecorder.h"
#include "model/numberformat.h"
#include "ui/appearance.h"

using namespace Qt::StringLiterals;

namespace Toffee {

namespace {

QScatterSeries *markers(
    const QString &name, QScatterSeries::MarkerShape shape, const QColor &color, qreal size)
{
    auto *series = new QScatterSeries;
    series->setName(name);
    series->setMarkerShape(shape);
    series->setMarkerSize(size);
    series->setColor(color);
    series->setBorderColor(color.darker(130));
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

HistoryDock::HistoryDock(HistoryRecorder *recorder, QWidget *parent)
    : QDockWidget(tr("History"), parent)
    , m_recorder(recorder)
    , m_title(new QLabel(this))
    , m_view(new QChartView(this))
    , m_table(new QTableView(this))
    , m_model(new QStandardItemModel(this))
    , m_export(new QPushButton(tr("Export CSV…"), this))
    , m_copy(new QPushButton(tr("Copy Chart"), this))
{
    setObjectName(u"historyDock"_s);
    m_title->setObjectName(u"historyTitle"_s);
    m_view->setObjectName(u"historyChart"_s);
    m_view->setRenderHint(QPainter::Antialiasing);
    m_view->setMinimumHeight(180);
    m_view->setAccessibleName(tr("TLO over time"));
    m_table->setObjectName(u"historyTable"_s);
    m_table->setModel(m_model);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_table->verticalHeader()->hide();
    m_table->setAccessibleName(tr("Measurements"));
    m_export->setObjectName(u"historyExportButton"_s);
    m_copy->setObjectName(u"historyCopyButton"_s);
    connect(m_copy, &QPushButton::clicked, this, &HistoryDock::copyChart);
    // Export asks the window for a file name: it is wired where the dialogs live.

    auto *split = new QSplitter(Qt::Vertical, this);
    split->addWidget(m_view);
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
    return m_view->chart();
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
    chart->setTitleBrush(text);
    chart->legend()->setLabelColor(text);
    auto *probes
        = markers(tr("Probes"), QScatterSeries::MarkerShapeCircle, palette().color(QPalette::Highlight), 8);
    auto *passed
        = markers(tr("Break test passed"), QScatterSeries::MarkerShapeTriangle, QColor(0x26, 0xa2, 0x69), 10);
    auto *failed = markers(tr("Break test failed"), QScatterSeries::MarkerShapeTriangle, alarm, 12);
    auto *manual
        = markers(tr("Set by hand"), QScatterSeries::MarkerShapeRectangle, QColor(0x98, 0x6a, 0x44), 8);
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
    QChart *old = m_view->chart();
    m_view->setChart(chart);
    delete old;
}

void HistoryDock::fillTable()
{
    m_model->clear();
    m_model->setHorizontalHeaderLabels({ tr("Time"), tr("Kind"), tr("TLO"), tr("Reference Z"),
        tr("Current Z"), tr("Tolerance"), tr("Old TLO"), tr("New TLO"), tr("Result") });
    const QLocale locale;
    // Newest first: the last measurement is the one an operator looks for.
    for (auto it = m_events.crbegin(); it != m_events.crend(); ++it) {
        const HistoryEvent &e = *it;
        QList<QStandardItem *> row {
            new QStandardItem(locale.toString(e.at.toLocalTime(), QLocale::ShortFormat)),
            new QStandardItem(kindText(e.kind)),
            new QStandardItem(lengthCell(e.tlo)),
            new QStandardItem(lengthCell(e.referenceMz)),
            new QStandardItem(lengthCell(e.currentMz)),
            new QStandardItem(lengthCell(e.tolerance)),
            new QStandardItem(lengthCell(e.oldTlo)),
            new QStandardItem(lengthCell(e.newTlo)),
            new QStandardItem(!e.failed ? QString()
                    : *e.failed         ? tr("BROKEN?")
                                        : tr("passed")),
        };
        for (qsizetype c = 2; c < 8; ++c)
            row.at(c)->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        if (e.failed.value_or(false))
            row.last()->setForeground(alarmColor(palette()));
        m_model->appendRow(row);
    }
    m_table->resizeColumnsToContents();
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
    QGuiApplication::clipboard()->setImage(m_view->grab().toImage());
}

} // namespace Toffee
