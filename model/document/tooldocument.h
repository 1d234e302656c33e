// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QObject>
#include <QUndoStack>

#include "model/document/tooltablemodel.h"
#include "model/formats/tablefile.h"
#include "model/library/outboxpayload.h"

namespace Toffee {

// An open tool table: the model, its file and format, and the one undo stack every edit goes through.
// Saved means "the undo stack is at its clean index".
class ToolDocument final : public QObject
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(ToolDocument)

public:
    explicit ToolDocument(QObject *parent = nullptr);
    ~ToolDocument() override;

    [[nodiscard]] ToolTableModel *model() { return &m_model; }
    [[nodiscard]] QUndoStack *undoStack() { return &m_undoStack; }
    [[nodiscard]] const ToolTable &table() const { return m_model.table(); }
    [[nodiscard]] QString filePath() const { return m_filePath; }
    [[nodiscard]] TableFormat fileFormat() const { return m_fileFormat; }
    [[nodiscard]] bool isModified() const { return !m_undoStack.isClean(); }

    void newTable(Units units = Units::Millimetre);
    Result<void> open(
        const QString &path, std::optional<TableFormat> format = {}, Units tblUnits = Units::Millimetre);
    Result<void> save();
    Result<void> saveAs(const QString &path, TableFormat format);
    // Writes a copy; the document keeps its own file and its modified state.
    [[nodiscard]] Result<void> exportTo(const QString &path, TableFormat format) const;
    // Merges another file's tools in as one undoable step: same numbers are replaced, new ones added.
    // Returns how many tools it brought in.
    Result<int> importFrom(
        const QString &path, std::optional<TableFormat> format = {}, Units tblUnits = Units::Millimetre);

    // Puts `table` in place of the whole table as one undoable step named `undoText` (a CAM import's merge).
    // Returns false, with no step, when it is the table already.
    bool replaceTable(const ToolTable &table, const QString &undoText);

    // Unsaved edits brought back after a crash (AutoSave), on top of the file they were made to as one
    // undoable step: the document is left modified, and Undo shows the file as it is on disk. With no file to
    // start from, the edits become a new table. Returns what the operator should know about that, or nothing.
    QString recoverEdits(const ToolTable &edits, const QString &originalPath, TableFormat originalFormat);

    Result<void> addTool(const Tool &tool);
    Result<void> editTool(int number, const Tool &after);
    void removeTools(const QList<int> &numbers);
    // A TLO from the machine (probed, or set there by hand), as one undoable step; the tool is added when the
    // table has none.
    Result<void> recordMeasurement(int number, double tlo, const QDateTime &at,
        TloSource source = TloSource::Probe, std::optional<double> referenceMz = std::nullopt);
    // A break test's verdict on tool `number`, as one undoable step (a failed tool stays marked).
    Result<void> recordBreakTest(int number, bool failed);
    // What an operation on the machine carries, recorded as one of the two above.
    Result<void> record(const Recording &recording);
    // Several at once, as one undoable step `text`: all of them, or none (ToolTable::recordAll).
    Result<void> recordAll(const QList<Recording> &recordings, const QString &text);
    // A new tool with the next free number and its default pocket.
    [[nodiscard]] Tool newTool() const;

    // A machine's table kept in a library (librarydocument.cpp). Save writes the tools that changed since
    // they were read, each over the version read, so that nothing another station wrote is overwritten.
    [[nodiscard]] bool isLibraryTable() const { return !m_base.machine.isEmpty(); }
    [[nodiscard]] QString libraryMachine() const { return m_base.machine; }
    void openLibraryTable(const StoredTable &stored);
    // The tools that differ from what the library held when they were read.
    [[nodiscard]] ToolWrites libraryWrites() const;
    // After a write: each written tool is what the library holds now; with nothing left to write the table
    // is saved. Writes kept in the outbox count as saved here; the library checks them when they are sent.
    void markWritten(const ToolWrites &writes, const WriteOutcome &outcome);
    // Another station's change. A tool not edited here takes theirs; one edited here is merged field by
    // field. Undo then starts from there (it would put their old values back). Returns the tools that cannot
    // be merged: the operator chooses (resolveConflict).
    QList<ToolConflict> takeRemote(const StoredTable &latest);
    // Theirs replaces the tool here (one undoable step); mine stays, to be written over theirs at Save.
    void resolveConflict(const ToolConflict &conflict, bool keepMine);

Q_SIGNALS:
    void modifiedChanged(bool modified);
    void filePathChanged(const QString &path);
    // An operation on the machine was recorded (whether or not the table could take it): for the history.
    void recorded(const Toffee::Recording &recording);

private:
    // `changed` replaces the tool with its number, or is added, as one undoable step named `text`.
    void pushChange(const Tool &changed, const QString &text);
    void setFile(const QString &path, TableFormat format);
    void setBaseRow(int number, const std::optional<Tool> &tool, qint64 version);
    void cleanWhenWritten();
    void applyTable(const ToolTable &next, const QString &text);
    void forgetUndoPast(const ToolTable &next);

    ToolTableModel m_model;
    QUndoStack m_undoStack;
    QString m_filePath;
    TableFormat m_fileFormat = TableFormat::Json;
    StoredTable m_base; // a library table's tools as last read or written
    QHash<int, std::optional<Tool>> m_queued; // tools saved into the outbox, not yet sent
};

} // namespace Toffee
