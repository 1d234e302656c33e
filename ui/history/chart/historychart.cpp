// SPDX-License-Identifier: GPL-3.0-or-later
// toffee_historychart: one tool's TLO over time as a Qt Charts chart (historychart.h says why it is a
// module).
#include "ui/history/chart/historychart.h"

#include <algorithm>
#include <limits>

#include <QAreaSeries>
#include <QChart>
#include <QChartView>
#include <QDateTimeAxis>
#include <QLineSeries>
#include <QLocale>
#include <QPainter>
#include <QValueAxis>

#include "model/clock.h"

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

QChart *emptyChart(const QPalette &palette)
{
    auto *chart = new QChart;
    chart->setMargins(QMargins(4, 4, 4, 4));
    chart->legend()->setAlignment(Qt::AlignBottom);
    chart->setBackgroundBrush(palette.brush(QPalette::Base));
    // The axis labels in the user's decimal mark ("-33,400" in German), like every other number in the
    // window.
    chart->setLocalizeNumbers(true);
    chart->setLocale(QLocale());
    chart->setTitleBrush(palette.color(QPalette::Text));
    chart->legend()->setLabelColor(palette.color(QPalette::Text));
    return chart;
}

// The measurements as marker series: probes, break tests passed and failed, values set by hand.
QList<QAbstractSeries *> measurementSeries(const HistoryChartInput &in, QList<QPointF> &probeTimes)
{
    auto *probes = markers(in.words.probes, MarkerShape::Circle, in.palette.color(QPalette::Highlight), 8);
    auto *passed = markers(in.words.passed, MarkerShape::Triangle, QColor(0x26, 0xa2, 0x69), 11);
    auto *failed = markers(in.words.failed, MarkerShape::Triangle, in.alarm, 13);
    auto *manual = markers(in.words.manual, MarkerShape::Square, QColor(0x98, 0x6a, 0x44), 9);
    auto *old = markers(in.words.oldCutter, MarkerShape::Circle, QColor(0x9a, 0x99, 0x96), 7);
    // The probes of a cutter that a new one ended are drawn apart, and are not on the trend.
    const QDateTime since = cutterSince(*in.events);
    for (const HistoryEvent &e : *in.events) {
        const qreal t = qreal(e.at.toMSecsSinceEpoch());
        if (e.kind == EventKind::BreakTest && (e.newTlo || e.tlo))
            (e.failed.value_or(false) ? failed : passed)->append(t, e.newTlo.value_or(*e.tlo));
        else if (e.kind == EventKind::Probe && e.tlo && since.isValid() && e.at <= since)
            old->append(t, *e.tlo);
        else if (e.kind == EventKind::Probe && e.tlo)
            probeTimes.append({ t, *e.tlo });
        else if (e.tlo)
            manual->append(t, *e.tlo);
    }
    probes->replace(probeTimes);
    QList<QAbstractSeries *> out { probes, passed, failed, manual };
    // A tool touched on each edge: every edge's TLO at its measurement (the measurement's is the highest's),
    // so that the spread and how it grows over time are seen beside the TLO.
    QList<QPointF> edges;
    for (const HistoryEvent &e : *in.events) {
        const std::optional<double> tlo = e.kind == EventKind::BreakTest ? e.newTlo : e.tlo;
        if (e.touches.size() < 2 || !tlo)
            continue;
        const double highest = highestTouch(e.touches);
        for (double z : e.touches)
            edges.append({ qreal(e.at.toMSecsSinceEpoch()), *tlo - (highest - z) });
    }
    if (!edges.isEmpty()) {
        auto *each = markers(in.words.edges, MarkerShape::Circle, in.palette.color(QPalette::Mid), 5);
        each->replace(edges);
        out.prepend(each); // beneath the measurements' own markers
    }
    if (old->count() > 0)
        out.append(old);
    else
        delete old;
    return out;
}

// The trend at each probe's place in the tool's life, drawn at the probe's time, with ± the tolerance.
QList<QAbstractSeries *> trendSeries(const HistoryChartInput &in, const QList<QPointF> &probeTimes)
{
    const auto &trend = in.trend;
    if (!trend || trend->points < 2 || probeTimes.size() != in.points.size())
        return {};
    auto *line = new QLineSeries;
    auto *upper = new QLineSeries;
    auto *lower = new QLineSeries;
    line->setName(in.words.trend);
    for (qsizetype i = 0; i < in.points.size(); ++i) {
        const qreal y = trend->predict(in.points.at(i).x);
        line->append(probeTimes.at(i).x(), y);
        upper->append(probeTimes.at(i).x(), y + in.tolerance);
        lower->append(probeTimes.at(i).x(), y - in.tolerance);
    }
    auto *band = new QAreaSeries(upper, lower);
    band->setName(in.words.band);
    QColor fill = in.palette.color(QPalette::Highlight);
    fill.setAlpha(40);
    band->setBrush(fill);
    band->setPen(Qt::NoPen);
    line->setPen(QPen(in.palette.color(QPalette::Highlight), 1.5, Qt::DashLine));
    return { band, line };
}

// Both axes over what is drawn, padded; with nothing to draw, today around zero, and no axes shown.
void addAxes(QChart *chart, const QList<QAbstractSeries *> &all, const HistoryChartInput &in)
{
    auto *time = new QDateTimeAxis;
    time->setFormat(QLocale().dateFormat(QLocale::ShortFormat));
    auto *tlo = new QValueAxis;
    tlo->setTitleText(in.words.tloAxis);
    tlo->setTitleBrush(in.palette.color(QPalette::Text));
    tlo->setLabelFormat(u"%.3f"_s);
    chart->addAxis(time, Qt::AlignBottom);
    chart->addAxis(tlo, Qt::AlignLeft);
    // Set once the chart's theme has dressed the axes: grid lines that stay in the background on the light
    // and the dark palette alike.
    const QColor grid = in.palette.color(QPalette::Text).lightness() > 128 ? QColor(0x55, 0x55, 0x55)
                                                                           : QColor(0xd0, 0xd0, 0xd0);
    for (QAbstractAxis *axis : { static_cast<QAbstractAxis *>(time), static_cast<QAbstractAxis *>(tlo) }) {
        axis->setGridLineColor(grid);
        axis->setLinePenColor(grid);
        axis->setLabelsBrush(in.palette.color(QPalette::Text));
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
        x0 = qreal(Clock::now().toMSecsSinceEpoch());
        x1 = x0;
        y0 = y1 = 0.0;
    }
    // The measurements fill the axis: four probes a minute apart are not lost on an axis of hours. A lone
    // one sits in the middle of ten minutes.
    const qreal minute = 60.0 * 1000.0;
    const qreal hour = 60.0 * minute;
    const qreal xPad = std::max(x1 > x0 ? minute / 2.0 : 5.0 * minute, (x1 - x0) * 0.05);
    const qreal yPad = std::max(0.05, (y1 - y0) * 0.1);
    time->setRange(
        QDateTime::fromMSecsSinceEpoch(qint64(x0 - xPad)), QDateTime::fromMSecsSinceEpoch(qint64(x1 + xPad)));
    tlo->setRange(y0 - yPad, y1 + yPad);
    // Three ticks to start from: the panel is short at 1280×720, and Qt Charts cuts a label that does not fit
    // between its neighbours to "..." (five ticks left every TLO unreadable there).
    tlo->setTickCount(3);
    tlo->applyNiceNumbers(); // ticks at round millimetres, not at the data's own edges
    // Within a few days the dates repeat: show the times, with seconds within the hour. With nothing to
    // draw, no axes at all.
    const qreal span = x1 + xPad - (x0 - xPad);
    if (span < hour)
        time->setFormat(u"HH:mm:ss"_s);
    else if (span < 3 * 24 * hour)
        time->setFormat(QLocale().timeFormat(QLocale::ShortFormat));
    time->setTickCount(span < 3 * 24 * hour ? 4 : 5);
    time->setVisible(!in.events->isEmpty());
    tlo->setVisible(!in.events->isEmpty());
}

} // namespace

} // namespace Toffee

extern "C" Q_DECL_EXPORT QWidget *toffee_history_chart_view(QWidget *parent)
{
    auto *view = new QChartView(parent);
    view->setRenderHint(QPainter::Antialiasing);
    return view;
}

extern "C" Q_DECL_EXPORT void toffee_history_chart_fill(QWidget *widget, const Toffee::HistoryChartInput &in)
{
    using namespace Toffee;
    auto *view = qobject_cast<QChartView *>(widget);
    if (!view || !in.events)
        return;
    QChart *chart = emptyChart(in.palette);
    QList<QPointF> probeTimes;
    QList<QAbstractSeries *> all = measurementSeries(in, probeTimes);
    all = trendSeries(in, probeTimes) + all;
    for (QAbstractSeries *s : all)
        chart->addSeries(s);
    if (!in.words.title.isEmpty())
        chart->setTitle(in.words.title);
    addAxes(chart, all, in);
    QChart *old = view->chart();
    view->setChart(chart);
    delete old;
}
