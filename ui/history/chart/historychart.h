// SPDX-License-Identifier: GPL-3.0-or-later
// The History panel's chart, in a module of its own (toffee_historychart, on Qt Charts): the window loads it
// the first time the panel is seen, so that Qt Charts and the OpenGL libraries it links are not loaded at
// every start (issue 16). The panel hands it what to draw, its words already translated.
#pragma once

#include <optional>

#include <QColor>
#include <QList>
#include <QPalette>
#include <QString>

#include "model/library/historyevent.h"
#include "model/library/weartrend.h"

class QWidget;

namespace Toffee {

// The legend's, the title's and the axis's words, in the window's language.
struct HistoryChartWords
{
    QString probes;
    QString passed;
    QString failed;
    QString manual;
    QString oldCutter; // probes of a cutter a new cutter ended
    QString trend;
    QString edges; // each touch of a tool touched once per cutting edge
    QString band; // "± 0.1 mm"
    QString title; // empty: none
    QString tloAxis;
};

struct HistoryChartInput
{
    const QList<HistoryEvent> *events = nullptr;
    std::optional<WearTrend> trend;
    QList<TrendPoint> points;
    double tolerance = 0.1;
    QPalette palette;
    QColor alarm;
    HistoryChartWords words;
};

// toffee_history_chart_view(parent): a new, empty chart view (a QChartView).
using MakeHistoryChartView = QWidget *(*)(QWidget *parent);
// toffee_history_chart_fill(view, input): the view shows a new chart of `input`.
using FillHistoryChart = void (*)(QWidget *view, const HistoryChartInput &input);
inline constexpr char kHistoryChartModule[] = "toffee_historychart.so";
inline constexpr char kMakeHistoryChartViewSymbol[] = "toffee_history_chart_view";
inline constexpr char kFillHistoryChartSymbol[] = "toffee_history_chart_fill";

} // namespace Toffee
