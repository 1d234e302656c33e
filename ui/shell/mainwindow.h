// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <QMainWindow>
#include <QPointer>

#include "model/library/historyevent.h"
#include "model/library/librarylocation.h"
#include "model/library/storedtable.h"
#include "model/toolsetter.h"

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QTimer;
class QDragEnterEvent;
class QDropEvent;

namespace Toffee {

class AutoSave;
struct MachineIdentity;
class ConsoleDock;
class FileWatcher;
class HistoryDock;
class HistoryRecorder;
class JobCheckDialog;
class Library;
class LibraryStatusLabel;
class MachineConnection;
class MachineDock;
class RackPanel;
class ToolDocument;
class ToolTablePanel;

// Wires the panels, actions and the document together; the work is done by the classes it wires.
class MainWindow final : public QMainWindow
{
    Q_OBJECT
    Q_DISABLE_COPY_MOVE(MainWindow)

public:
    // Build::AfterShow makes only the frame, for start-up to show it first; build() then fills it.
    enum class Build { Now, AfterShow };
    explicit MainWindow(QWidget *parent = nullptr);
    explicit MainWindow(Build when, QWidget *parent = nullptr);
    void build(); // once; the panels, docks, menus and connections
    void showThenBuild();
    ~MainWindow() override;

    [[nodiscard]] ToolDocument *document() const { return m_document; }
    [[nodiscard]] ToolTablePanel *toolTablePanel() const { return m_tablePanel; }
    [[nodiscard]] MachineConnection *connection() const { return m_connection; }
    [[nodiscard]] MachineDock *machineDock() const { return m_machineDock; }
    [[nodiscard]] ConsoleDock *consoleDock() const { return m_consoleDock; }
    [[nodiscard]] AutoSave *autoSave() const { return m_autoSave; }
    [[nodiscard]] HistoryRecorder *history() const { return m_history; }
    [[nodiscard]] HistoryDock *historyDock() const { return m_historyDock; }
    [[nodiscard]] RackPanel *rackPanel() const { return m_rackPanel; }
    // The program's use of each tool, recorded (what Record a Program Run does once a file is chosen).
    Result<int> recordProgramRun(const QString &path);
    // The history library every measurement goes into (--library, or the setting, or the standard one),
    // written as `station` (the computer's name when empty). A shared library that cannot be used as it is
    // set (a wrong URL, password, database or server) is said so, and the station's own library is used.
    void setLibrary(const LibraryLocation &location, const QString &station = {});
    // A library named as Toffee cannot read it (--library with a password, an unknown setting): said, and
    // the station's own library is used.
    void refuseLibrary(const QString &message);
    // File ▸ Open Machine Table… once the machine is chosen: false, with a message box, when it fails.
    bool openMachineTable(const QString &machine);
    // File ▸ Save to Library… once the name is given: the table becomes that machine's table in the library.
    bool saveToLibrary(const QString &machine);
    // Opens a table, reporting a failure in a message box; the current table stays if it fails.
    bool openFile(const QString &path);
    // File ▸ Check Job… once a program is chosen (or dropped on the window): the check starts at once.
    JobCheckDialog *openJobCheck(const QString &path);
    // File ▸ Import once a file is chosen: a CAM library through its preview, a table merged as it is. False
    // when nothing was imported (refused, with a message box, or cancelled).
    bool importFile(const QString &path);

protected:
    void closeEvent(QCloseEvent *event) override;
    // The panels below the table (console, history) keep their share of the height as the window grows or
    // shrinks: the History chart grows with the window, not only the table.
    void resizeEvent(QResizeEvent *event) override;
    void dragEnterEvent(QDragEnterEvent *event) override;
    void dropEvent(QDropEvent *event) override;

private:
    template<typename Slot>
    QAction *addMenuAction(
        QMenu *menu, const QString &name, const QString &text, const QKeySequence &shortcut, Slot slot);
    void createActions();
    void createLanguageMenu(QMenu *view);
    void createMachineActions();
    void createMachineStrip();
    void createRackDock();
    void connectMachine();
    void offerReconnect(const QString &operation, const QString &reason);
    void connectDocument();
    void updateMachineStatus();
    void fileChangedOnDisk(const QString &path);
    void newTable();
    void open();
    bool save();
    bool saveAs();
    void importTable();
    bool importCamLibrary(const QString &path);
    void exportTable();
    void addTool();
    void removeTools();
    // Edit ▸ New Cutter…: the selected tool's pocket holds another cutter (asked first).
    void newCutter();
    bool maybeSave();
    bool confirmLossySave(const QString &path);
    void updateTitle();
    void updateRecentFiles();
    // The file now open or saved: watched for outside changes, first of the recent files.
    void rememberFile(const QString &path);
    void showError(const QString &title, const QString &message);
    void connectHistory();
    void recordHistory(const Recording &recording);
    void checkTrends(const QList<HistoryEvent> &events);
    void showSelectedHistory();
    void refreshToolLife();
    // File ▸ Record a Program Run…: the program ran on this machine; each tool's cutting time is recorded.
    void recordProgramRun();
    // Machine ▸ History Library…: the library, this machine's name in it, the stale limit.
    void editHistorySettings();
    void exportHistory();
    void checkJob();
    [[nodiscard]] std::optional<double> machineReference() const;
    // A grblHAL machine's setter and reference, and its own table (mainwindowcontroller.cpp).
    void connectControllerSettings();
    [[nodiscard]] std::optional<double> keptReference() const;
    [[nodiscard]] QString bindMachine(const MachineIdentity &identity);
    [[nodiscard]] std::optional<ToolSetter> machineToolSetter() const;
    void editToolSetter();
    void editLinuxCncAccess();
    void pushOffsets();
    void pullOffsets();
    void restoreWindowGeometry();
    void restoreDockState();
    void writeSettings();
    // Machine tables in the library (librarytables.cpp, libraryupdates.cpp).
    void createLibraryActions(QMenu *file);
    void connectLibrary();
    void chooseMachineTable();
    void askSaveToLibrary();
    bool saveLibraryTable();
    void showLibraryTable(const Library &library, const StoredTable &stored);
    [[nodiscard]] QString libraryTableTitle() const;
    [[nodiscard]] bool showsLibraryTable(const QString &machine) const;
    // The machine the table on screen belongs to: a library table's own, else the setting's (History
    // Library…). Measurements are recorded, and the history read, under it.
    [[nodiscard]] QString machineName() const;
    [[nodiscard]] bool hasUnsavedEdits() const;
    void updateLibraryState();
    void takeLibraryChange(const QString &machine);
    void refreshLibraryTable(const QString &machine);
    void adoptReplayed(const QString &machine, const WriteOutcome &outcome);
    void chooseReplayed(const QString &machine, QList<ToolConflict> conflicts);
    // The operator chooses per tool; theirs are taken, mine saved again. True when all is saved.
    bool chooseConflicts(const QList<ToolConflict> &conflicts);
    // The shared library cannot be used as set: said, and the station's own library is used.
    void useOwnLibrary(const QString &message);

    ToolDocument *m_document = nullptr;
    ToolTablePanel *m_tablePanel = nullptr;
    MachineConnection *m_connection = nullptr;
    MachineDock *m_machineDock = nullptr;
    ConsoleDock *m_consoleDock = nullptr;
    QLabel *m_machineLabel = nullptr;
    FileWatcher *m_fileWatcher = nullptr;
    AutoSave *m_autoSave = nullptr;
    HistoryRecorder *m_history = nullptr;
    HistoryDock *m_historyDock = nullptr;
    RackPanel *m_rackPanel = nullptr;
    QAction *m_pushOffsetsAction = nullptr;
    QAction *m_pullOffsetsAction = nullptr;
    QDockWidget *m_rackDock = nullptr;
    QMenu *m_recentMenu = nullptr;
    QAction *m_newCutterAction = nullptr;
    QAction *m_removeAction = nullptr;
    QLabel *m_countLabel = nullptr;
    LibraryStatusLabel *m_libraryLabel = nullptr;
    QTimer *m_remoteRetry = nullptr; // takes another station's change once a cell is no longer edited
    QString m_station; // who this window writes as in the library; empty: the computer's name
    bool m_newMachine = false; // the machine connected to is new to the library: nothing of it adopted
    LibraryLocation m_tableLibrary; // where the open machine table came from
    bool m_tableReadOnly = false; // and whether that library may be written
    // A library table this station may only read: nothing measured could be kept, so nothing is measured.
    [[nodiscard]] bool recordingBlocked() const;
    LibraryLocation m_askedLibrary; // what setLibrary was given, also when the window fell back to its own
    QPointer<JobCheckDialog> m_jobDialog; // it deletes itself on closing
};

} // namespace Toffee
