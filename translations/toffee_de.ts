<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>BrokenTool</name>
    <message>
        <source>T%1 is marked broken: it failed its break test. Probing measures it as it is now, records that TLO and clears the mark: replace the tool first if it is broken.</source>
        <translation>T%1 ist als gebrochen markiert: Es hat seinen Bruchtest nicht bestanden. Das Messen erfasst es, wie es jetzt ist, zeichnet diese Längenkorrektur auf und hebt die Markierung auf: Ersetzen Sie das Werkzeug zuerst, wenn es gebrochen ist.</translation>
    </message>
    <message>
        <source>T%1 is marked broken: it failed its break test. A TLO set by hand does not clear the mark; measure the tool (Probe) once it is checked or replaced.</source>
        <translation>T%1 ist als gebrochen markiert: Es hat seinen Bruchtest nicht bestanden. Eine von Hand gesetzte Längenkorrektur hebt die Markierung nicht auf; messen Sie das Werkzeug (Messen), sobald es geprüft oder ersetzt ist.</translation>
    </message>
    <message>
        <source>T%1 is marked broken: it failed its last break test. Testing it again compares it with its stored TLO; a pass clears the mark.</source>
        <translation>T%1 ist als gebrochen markiert: Es hat seinen letzten Bruchtest nicht bestanden. Ein erneuter Test vergleicht es mit seiner gespeicherten Längenkorrektur; ein Bestehen hebt die Markierung auf.</translation>
    </message>
</context>
<context>
    <name>Toffee</name>
    <message>
        <source>tool number %1 is out of range; use %2 to %3.</source>
        <translation>Werkzeugnummer %1 liegt außerhalb des Bereichs; verwenden Sie %2 bis %3.</translation>
    </message>
    <message>
        <source>pocket %1 is out of range; use %2 to %3.</source>
        <translation>Platz %1 liegt außerhalb des Bereichs; verwenden Sie %2 bis %3.</translation>
    </message>
    <message>
        <source>%1 is not a number; enter a value from %2 to %3 %4.</source>
        <translation>%1 ist keine Zahl; geben Sie einen Wert von %2 bis %3 %4 ein.</translation>
    </message>
    <message>
        <source>%1 %2 %3 is out of range; a controller takes %4 to %5 %3.</source>
        <translation>%1 %2 %3 liegt außerhalb des Bereichs; eine Steuerung nimmt %4 bis %5 %3.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a LinuxCNC tool field (X, Y, A, B, C, U, V, W, I, J or Q0-Q9).</source>
        <translation>„%1“ ist kein LinuxCNC-Werkzeugfeld (X, Y, A, B, C, U, V, W, I, J oder Q0-Q9).</translation>
    </message>
    <message>
        <source>the description is %1 characters long; keep it to %2.</source>
        <translation>Die Beschreibung ist %1 Zeichen lang; höchstens %2 sind erlaubt.</translation>
    </message>
    <message>
        <source>the description must be one line of text, without tabs or line breaks.</source>
        <translation>Die Beschreibung muss eine Textzeile sein, ohne Tabulatoren oder Zeilenumbrüche.</translation>
    </message>
    <message>
        <source>the notes are %1 characters long; keep them to %2.</source>
        <translation>Die Notizen sind %1 Zeichen lang; höchstens %2 sind erlaubt.</translation>
    </message>
    <message>
        <source>length geometry</source>
        <translation>Längengeometrie</translation>
    </message>
    <message>
        <source>length wear</source>
        <translation>Längenverschleiß</translation>
    </message>
    <message>
        <source>radius geometry</source>
        <translation>Radiusgeometrie</translation>
    </message>
    <message>
        <source>radius wear</source>
        <translation>Radiusverschleiß</translation>
    </message>
    <message>
        <source>measured TLO</source>
        <translation>gemessene Werkzeuglängenkorrektur</translation>
    </message>
    <message>
        <source>tool number %1 is already in the table; tool numbers must be unique.</source>
        <translation>Werkzeugnummer %1 ist schon in der Tabelle; Werkzeugnummern müssen eindeutig sein.</translation>
    </message>
    <message>
        <source>Toffee tool table (JSON)</source>
        <translation>Toffee-Werkzeugtabelle (JSON)</translation>
    </message>
    <message>
        <source>LinuxCNC tool table</source>
        <translation>LinuxCNC-Werkzeugtabelle</translation>
    </message>
    <message>
        <source>CSV spreadsheet</source>
        <translation>CSV-Tabelle</translation>
    </message>
    <message>
        <source>unknown table format.</source>
        <translation>Unbekanntes Tabellenformat.</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no wear columns: wear is added into the length and diameter.</source>
        <translation>Eine LinuxCNC-Tabelle hat keine Verschleißspalten: Der Verschleiß wird in Länge und Durchmesser eingerechnet.</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no place for measured TLOs: they are not saved.</source>
        <translation>Eine LinuxCNC-Tabelle hat keinen Platz für gemessene Längenkorrekturen: Sie werden nicht gespeichert.</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no place for notes: they are not saved.</source>
        <translation>Eine LinuxCNC-Tabelle hat keinen Platz für Notizen: Sie werden nicht gespeichert.</translation>
    </message>
    <message>
        <source>A LinuxCNC table does not record its units: the numbers are written in inches.</source>
        <translation>Eine LinuxCNC-Tabelle speichert keine Einheit: Die Zahlen werden in Zoll geschrieben.</translation>
    </message>
    <message>
        <source>%1: unknown file type; use a .json, .tbl or .csv file.</source>
        <translation>%1: unbekannter Dateityp; verwenden Sie eine .json-, .tbl- oder .csv-Datei.</translation>
    </message>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1: lässt sich nicht öffnen: %2</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1: lässt sich nicht lesen: %2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a whole number.</source>
        <translation>„%1“ muss eine ganze Zahl sein.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a number.</source>
        <translation>„%1“ muss eine Zahl sein.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be text.</source>
        <translation>„%1“ muss Text sein.</translation>
    </message>
    <message>
        <source>each entry of &quot;tools&quot; must be a JSON object such as {&quot;number&quot;: 1}.</source>
        <translation>Jeder Eintrag in „tools“ muss ein JSON-Objekt sein, etwa {&quot;number&quot;: 1}.</translation>
    </message>
    <message>
        <source>unknown field &quot;%1&quot; in a tool.</source>
        <translation>Unbekanntes Feld „%1“ in einem Werkzeug.</translation>
    </message>
    <message>
        <source>the field &quot;%1&quot; appears twice in a tool.</source>
        <translation>Das Feld „%1“ kommt in einem Werkzeug zweimal vor.</translation>
    </message>
    <message>
        <source>&quot;measured_at&quot; is not a date and time (use ISO 8601, e.g. 2026-11-22T10:15:00Z).</source>
        <translation>„measured_at“ ist kein Datum mit Uhrzeit (ISO 8601 verwenden, z. B. 2026-11-22T10:15:00Z).</translation>
    </message>
    <message>
        <source>a tool has no &quot;number&quot;.</source>
        <translation>Ein Werkzeug hat keine „number“.</translation>
    </message>
    <message>
        <source>this is not valid JSON: the file is empty.</source>
        <translation>Das ist kein gültiges JSON: Die Datei ist leer.</translation>
    </message>
    <message>
        <source>this is not a Toffee tool table: the file must hold one JSON object.</source>
        <translation>Das ist keine Toffee-Werkzeugtabelle: Die Datei muss genau ein JSON-Objekt enthalten.</translation>
    </message>
    <message>
        <source>this is not a Toffee tool table: &quot;format&quot; must be &quot;%1&quot;, before &quot;tools&quot;.</source>
        <translation>Das ist keine Toffee-Werkzeugtabelle: „format“ muss „%1“ sein und vor „tools“ stehen.</translation>
    </message>
    <message>
        <source>&quot;version&quot; must come before &quot;tools&quot;.</source>
        <translation>„version“ muss vor „tools“ stehen.</translation>
    </message>
    <message>
        <source>&quot;tools&quot; must be a list of tools.</source>
        <translation>„tools“ muss eine Liste von Werkzeugen sein.</translation>
    </message>
    <message>
        <source>this is not a Toffee tool table: &quot;format&quot; must be &quot;%1&quot;.</source>
        <translation>Das ist keine Toffee-Werkzeugtabelle: „format“ muss „%1“ sein.</translation>
    </message>
    <message>
        <source>&quot;version&quot; must be a whole number from 1 up.</source>
        <translation>„version“ muss eine ganze Zahl ab 1 sein.</translation>
    </message>
    <message>
        <source>this table was written by a newer Toffee (format version %1); this one reads up to version %2. Update Toffee to open it.</source>
        <translation>Diese Tabelle stammt von einem neueren Toffee (Formatversion %1); dieses liest bis Version %2. Aktualisieren Sie Toffee, um sie zu öffnen.</translation>
    </message>
    <message>
        <source>&quot;units&quot; must be &quot;mm&quot; or &quot;in&quot;.</source>
        <translation>„units“ muss „mm“ oder „in“ sein.</translation>
    </message>
    <message>
        <source>unknown field &quot;%1&quot; in the table.</source>
        <translation>Unbekanntes Feld „%1“ in der Tabelle.</translation>
    </message>
    <message>
        <source>this is not valid JSON: there is more text after the table.</source>
        <translation>Das ist kein gültiges JSON: Nach der Tabelle folgt weiterer Text.</translation>
    </message>
    <message>
        <source>the comment is not valid UTF-8 text.</source>
        <translation>Der Kommentar ist kein gültiger UTF-8-Text.</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the field %2 appears twice.</source>
        <translation>„%1“: Das Feld %2 kommt zweimal vor.</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 needs a whole number.</source>
        <translation>„%1“: %2 braucht eine ganze Zahl.</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the orientation Q must be 0 to 9.</source>
        <translation>„%1“: Die Orientierung Q muss 0 bis 9 sein.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a tool table field; a line holds T, P, X, Y, Z, A, B, C, U, V, W, D, I, J, Q and a ;comment.</source>
        <translation>„%1“ ist kein Feld einer Werkzeugtabelle; eine Zeile enthält T, P, X, Y, Z, A, B, C, U, V, W, D, I, J, Q und einen ;Kommentar.</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 needs a number.</source>
        <translation>„%1“: %2 braucht eine Zahl.</translation>
    </message>
    <message>
        <source>the line has no tool number (T).</source>
        <translation>Die Zeile hat keine Werkzeugnummer (T).</translation>
    </message>
    <message>
        <source>T%1 has no pocket (P).</source>
        <translation>T%1 hat keinen Platz (P).</translation>
    </message>
    <message>
        <source>T%1: pocket %2 is out of range; use %3 to %4.</source>
        <translation>T%1: Platz %2 liegt außerhalb des Bereichs; verwenden Sie %3 bis %4.</translation>
    </message>
    <message>
        <source>the file holds binary data; it is not a LinuxCNC tool table.</source>
        <translation>Die Datei enthält Binärdaten; sie ist keine LinuxCNC-Werkzeugtabelle.</translation>
    </message>
    <message>
        <source>a quoted field is never closed; add the closing quote (&quot;).</source>
        <translation>Ein Feld in Anführungszeichen wird nie geschlossen; ergänzen Sie das schließende Anführungszeichen (&quot;).</translation>
    </message>
    <message>
        <source>text after a closing quote; put the whole field in quotes.</source>
        <translation>Text nach einem schließenden Anführungszeichen; setzen Sie das ganze Feld in Anführungszeichen.</translation>
    </message>
    <message>
        <source>a quote (&quot;) inside an unquoted field; put the whole field in quotes and double the quote.</source>
        <translation>Ein Anführungszeichen (&quot;) in einem Feld ohne Anführungszeichen; setzen Sie das ganze Feld in Anführungszeichen und verdoppeln Sie das Zeichen.</translation>
    </message>
    <message>
        <source>the file holds binary data; it is not a CSV table.</source>
        <translation>Die Datei enthält Binärdaten; sie ist keine CSV-Tabelle.</translation>
    </message>
    <message>
        <source>the file is not UTF-8 text; save it from the spreadsheet as &quot;CSV UTF-8&quot;.</source>
        <translation>Die Datei ist kein UTF-8-Text; speichern Sie sie in der Tabellenkalkulation als „CSV UTF-8“.</translation>
    </message>
    <message>
        <source>the file is empty; a CSV tool table starts with a header row such as &quot;number,pocket,description,...&quot;.</source>
        <translation>Die Datei ist leer; eine CSV-Werkzeugtabelle beginnt mit einer Kopfzeile wie „number,pocket,description,...“.</translation>
    </message>
    <message>
        <source>the column &quot;%1&quot; appears twice in the header.</source>
        <translation>Die Spalte „%1“ kommt in der Kopfzeile zweimal vor.</translation>
    </message>
    <message>
        <source>the header has no &quot;number&quot; column.</source>
        <translation>Die Kopfzeile hat keine Spalte „number“.</translation>
    </message>
    <message>
        <source>this row has %1 fields but the header has %2.</source>
        <translation>Diese Zeile hat %1 Felder, die Kopfzeile aber %2.</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; is not a number.</source>
        <translation>%1 „%2“ ist keine Zahl.</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; is not a whole number.</source>
        <translation>%1 „%2“ ist keine ganze Zahl.</translation>
    </message>
    <message>
        <source>the row has no tool number.</source>
        <translation>Die Zeile hat keine Werkzeugnummer.</translation>
    </message>
    <message>
        <source>measured_at &quot;%1&quot; is not a date and time (use ISO 8601, e.g. 2026-11-22T10:15:00Z).</source>
        <translation>measured_at „%1“ ist kein Datum mit Uhrzeit (ISO 8601 verwenden, z. B. 2026-11-22T10:15:00Z).</translation>
    </message>
    <message>
        <source>units &quot;%1&quot; must be mm or in.</source>
        <translation>Einheit „%1“ muss mm oder in sein.</translation>
    </message>
    <message>
        <source>this row is in %1 but the rows above are in %2; a table has one unit.</source>
        <translation>Diese Zeile ist in %1, die Zeilen darüber aber in %2; eine Tabelle hat eine Einheit.</translation>
    </message>
    <message>
        <source>T%1 cannot be written: %2 offset numbers go from 1 to %3.</source>
        <translation>T%1 lässt sich nicht schreiben: %2-Korrekturnummern gehen von 1 bis %3.</translation>
    </message>
    <message>
        <source>T%1 cannot be written: LinuxCNC&apos;s G10 L1 needs a tool number from 1 up.</source>
        <translation>T%1 lässt sich nicht schreiben: G10 L1 von LinuxCNC braucht eine Werkzeugnummer ab 1.</translation>
    </message>
    <message>
        <source>No tool has a measured TLO to write; probe the tools first.</source>
        <translation>Kein Werkzeug hat eine gemessene Längenkorrektur; vermessen Sie die Werkzeuge zuerst.</translation>
    </message>
    <message>
        <source>There is no tool %1 in the table.</source>
        <translation>Es gibt kein Werkzeug %1 in der Tabelle.</translation>
    </message>
    <message>
        <source>The table is empty.</source>
        <translation>Die Tabelle ist leer.</translation>
    </message>
    <message>
        <source>Toffee does not know how the FAGOR 8055M programs its offset table; enter the offsets at the control, or export for another dialect.</source>
        <translation>Toffee weiß nicht, wie die FAGOR 8055M ihre Korrekturtabelle programmiert; geben Sie die Korrekturen an der Steuerung ein oder exportieren Sie für eine andere Steuerung.</translation>
    </message>
    <message>
        <source>Unknown controller.</source>
        <translation>Unbekannte Steuerung.</translation>
    </message>
    <message>
        <source>%1… (%2 characters)</source>
        <translation>%1… (%2 Zeichen)</translation>
    </message>
    <message>
        <source>%1… (%2 bytes)</source>
        <translation>%1… (%2 Byte)</translation>
    </message>
    <message>
        <source>it is a named pipe (FIFO), not a file; Toffee opens only regular files.</source>
        <translation>Das ist eine benannte Pipe (FIFO), keine Datei; Toffee öffnet nur gewöhnliche Dateien.</translation>
    </message>
    <message>
        <source>it is a device, not a file; Toffee opens only regular files.</source>
        <translation>Das ist ein Gerät, keine Datei; Toffee öffnet nur gewöhnliche Dateien.</translation>
    </message>
    <message>
        <source>it is a folder, not a file.</source>
        <translation>Das ist ein Ordner, keine Datei.</translation>
    </message>
    <message>
        <source>it is a socket, not a file; Toffee opens only regular files.</source>
        <translation>Das ist ein Socket, keine Datei; Toffee öffnet nur gewöhnliche Dateien.</translation>
    </message>
    <message>
        <source>it is not a regular file; Toffee opens only regular files.</source>
        <translation>Das ist keine gewöhnliche Datei; Toffee öffnet nur gewöhnliche Dateien.</translation>
    </message>
    <message>
        <source>no file name was given.</source>
        <translation>Es wurde kein Dateiname angegeben.</translation>
    </message>
    <message>
        <source>%1: the file is %2 MB; Toffee reads files of at most %3 MB.</source>
        <translation>%1: Die Datei ist %2 MB groß; Toffee liest Dateien bis %3 MB.</translation>
    </message>
    <message>
        <source>%1: cannot save: %2 The old file is unchanged.</source>
        <translation>%1: Speichern nicht möglich: %2 Die alte Datei ist unverändert.</translation>
    </message>
    <message>
        <source>%1: cannot save: %2 Nothing was written.</source>
        <translation>%1: Speichern nicht möglich: %2 Es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>the file could not be written</source>
        <translation>die Datei ließ sich nicht schreiben</translation>
    </message>
    <message>
        <source>the table would take more than %1 MB, more than Toffee reads back; shorten the notes or split the table.</source>
        <translation>Die Tabelle bräuchte mehr als %1 MB, mehr als Toffee wieder einliest; kürzen Sie die Notizen oder teilen Sie die Tabelle.</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 is out of range; use %3 to %4.</source>
        <translation>„%1“: %2 liegt außerhalb des Bereichs; verwenden Sie %3 bis %4.</translation>
    </message>
    <message>
        <source>%1: there is not enough memory to read this table (the file is %2 MB).</source>
        <translation>%1: Es ist nicht genug Speicher da, um diese Tabelle zu lesen (die Datei ist %2 MB groß).</translation>
    </message>
    <message>
        <source>the comment &quot;%1&quot; is longer than a description may be (%2 characters).</source>
        <translation>Der Kommentar „%1“ ist länger, als eine Beschreibung sein darf (%2 Zeichen).</translation>
    </message>
    <message>
        <source>the field &quot;%1&quot; is longer than %2 KB; no column of a tool table holds that much.</source>
        <translation>Das Feld „%1“ ist länger als %2 KB; keine Spalte einer Werkzeugtabelle fasst so viel.</translation>
    </message>
    <message>
        <source>the header has more than %1 columns, more than a tool table has.</source>
        <translation>Die Kopfzeile hat mehr als %1 Spalten, mehr als eine Werkzeugtabelle hat.</translation>
    </message>
    <message>
        <source>this row has more fields than the header&apos;s %1.</source>
        <translation>Diese Zeile hat mehr Felder als die %1 der Kopfzeile.</translation>
    </message>
    <message>
        <source>%1: cannot save: %2</source>
        <translation>%1: Speichern nicht möglich: %2</translation>
    </message>
    <message>
        <source>the folder %1 does not exist.</source>
        <translation>Der Ordner %1 existiert nicht.</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>T%1 has no measured TLO to write; probe it first.</source>
        <translation>T%1 hat keine gemessene Längenkorrektur zum Schreiben; vermessen Sie es zuerst.</translation>
    </message>
    <message>
        <source>An Aerotech program sets the offsets of one tool at a time: choose the tool.</source>
        <translation>Ein Aerotech-Programm setzt die Korrekturen eines Werkzeugs nach dem anderen: Wählen Sie das Werkzeug.</translation>
    </message>
    <message>
        <source>a TLO set by hand needs its value; the measured TLO is empty.</source>
        <translation>Eine von Hand gesetzte TLO braucht ihren Wert; die gemessene TLO ist leer.</translation>
    </message>
    <message>
        <source>A LinuxCNC table cannot mark a tool that failed its break test: %1 would no longer be marked.</source>
        <translation>Eine LinuxCNC-Tabelle kann kein Werkzeug markieren, das seinen Bruchtest nicht bestanden hat: %1 wäre nicht mehr markiert.</translation>
    </message>
    <message>
        <source>break_test &quot;%1&quot; must be failed, passed or empty.</source>
        <translation>break_test &quot;%1&quot; muss failed, passed oder leer sein.</translation>
    </message>
    <message>
        <source>reference MCS Z</source>
        <translation>Referenz-MCS-Z</translation>
    </message>
    <message>
        <source>%1 is %2 %3; it cannot be negative.</source>
        <translation>%1 ist %2 %3; das kann nicht negativ sein.</translation>
    </message>
    <message>
        <source>the diameter</source>
        <translation>der Durchmesser</translation>
    </message>
    <message>
        <source>the flute length</source>
        <translation>die Schneidenlänge</translation>
    </message>
    <message>
        <source>the length below the holder</source>
        <translation>die Länge unter dem Halter</translation>
    </message>
    <message>
        <source>the overall length</source>
        <translation>die Gesamtlänge</translation>
    </message>
    <message>
        <source>%1: cannot open it.</source>
        <translation>%1: kann nicht geöffnet werden.</translation>
    </message>
    <message>
        <source>Fusion tool library (JSON)</source>
        <translation>Fusion-Werkzeugbibliothek (JSON)</translation>
    </message>
    <message>
        <source>Fusion tool library (.tools)</source>
        <translation>Fusion-Werkzeugbibliothek (.tools)</translation>
    </message>
    <message>
        <source>HSM tool library (.hsmlib)</source>
        <translation>HSM-Werkzeugbibliothek (.hsmlib)</translation>
    </message>
    <message>
        <source>Makera CAM program&apos;s tool header</source>
        <translation>Werkzeugkopf eines Makera-CAM-Programms</translation>
    </message>
    <message>
        <source>the library holds no tools; nothing to import.</source>
        <translation>die Bibliothek enthält keine Werkzeuge; nichts zu importieren.</translation>
    </message>
    <message>
        <source>number %1 is taken already (%2); each tool needs a number of its own.</source>
        <translation>die Nummer %1 ist schon vergeben (%2); jedes Werkzeug braucht eine eigene Nummer.</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>Zeile %1</translation>
    </message>
    <message>
        <source>%1: not a CAM tool library Toffee reads (.json, .tools, .hsmlib, or a G-code program with Makera CAM&apos;s tool header).</source>
        <translation>%1: keine CAM-Werkzeugbibliothek, die Toffee liest (.json, .tools, .hsmlib oder ein G-Code-Programm mit dem Werkzeugkopf von Makera CAM).</translation>
    </message>
    <message>
        <source>it unpacks to more than %1 MB; Toffee reads libraries of at most %1 MB.</source>
        <translation>entpackt ergibt sie mehr als %1 MB; Toffee liest Bibliotheken von höchstens %1 MB.</translation>
    </message>
    <message>
        <source>this is not a .tools archive Toffee can read: %1.</source>
        <translation>das ist kein .tools-Archiv, das Toffee lesen kann: %1.</translation>
    </message>
    <message>
        <source>it cannot be unpacked: %1.</source>
        <translation>sie lässt sich nicht entpacken: %1.</translation>
    </message>
    <message>
        <source>it is not a zip archive, or one cut short (there is no zip directory at its end)</source>
        <translation>es ist kein ZIP-Archiv oder eines, das abgeschnitten ist (an seinem Ende steht kein ZIP-Verzeichnis)</translation>
    </message>
    <message>
        <source>two of its entries have the same name, so it cannot be told which one is meant</source>
        <translation>zwei seiner Einträge haben denselben Namen, daher lässt sich nicht sagen, welcher gemeint ist</translation>
    </message>
    <message>
        <source>the archive is damaged (its directory and its entries disagree)</source>
        <translation>das Archiv ist beschädigt (sein Verzeichnis und seine Einträge passen nicht zusammen)</translation>
    </message>
    <message>
        <source>it is one part of an archive split over several files</source>
        <translation>es ist ein Teil eines auf mehrere Dateien verteilten Archivs</translation>
    </message>
    <message>
        <source>the archive is damaged (what it unpacks to fails its checksum)</source>
        <translation>das Archiv ist beschädigt (der entpackte Inhalt besteht die Prüfsumme nicht)</translation>
    </message>
    <message>
        <source>it is compressed in a way Toffee cannot unpack (Fusion&apos;s own archives use deflate)</source>
        <translation>es ist auf eine Weise komprimiert, die Toffee nicht entpacken kann (Fusions eigene Archive verwenden Deflate)</translation>
    </message>
    <message>
        <source>it is encrypted; Toffee reads archives without a password</source>
        <translation>es ist verschlüsselt; Toffee liest Archive ohne Passwort</translation>
    </message>
    <message>
        <source>its compressed data is damaged</source>
        <translation>seine komprimierten Daten sind beschädigt</translation>
    </message>
    <message>
        <source>the archive is truncated (it ends early)</source>
        <translation>das Archiv ist abgeschnitten (es endet zu früh)</translation>
    </message>
    <message>
        <source>there is not enough memory to unpack it</source>
        <translation>zum Entpacken ist nicht genug Speicher frei</translation>
    </message>
    <message>
        <source>libzip says: %1</source>
        <translation>libzip meldet: %1</translation>
    </message>
    <message>
        <source>this is not a .tools archive: the file is empty.</source>
        <translation>das ist kein .tools-Archiv: die Datei ist leer.</translation>
    </message>
    <message>
        <source>the archive holds no %1; a Fusion .tools file is a zip archive with the library in %1.</source>
        <translation>das Archiv enthält keine %1; eine Fusion-.tools-Datei ist ein ZIP-Archiv mit der Bibliothek in %1.</translation>
    </message>
    <message>
        <source>the archive holds %1 twice (%2 and %3); Toffee will not guess which one is the library.</source>
        <translation>das Archiv enthält %1 zweimal (%2 und %3); Toffee rät nicht, welche davon die Bibliothek ist.</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>eine Liste</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>ein Objekt</translation>
    </message>
    <message>
        <source>null</source>
        <translation>null</translation>
    </message>
    <message>
        <source>this is not a Fusion tool library: that is a JSON object with &quot;data&quot;, a list of tools.</source>
        <translation>das ist keine Fusion-Werkzeugbibliothek: die ist ein JSON-Objekt mit „data“, einer Liste von Werkzeugen.</translation>
    </message>
    <message>
        <source>tool %1 in &quot;data&quot;</source>
        <translation>Werkzeug %1 in „data“</translation>
    </message>
    <message>
        <source>it is %1, not an object.</source>
        <translation>es ist %1, kein Objekt.</translation>
    </message>
    <message>
        <source>%1=%2 is not a number.</source>
        <translation>%1=%2 ist keine Zahl.</translation>
    </message>
    <message>
        <source>number=%1 is not a tool number.</source>
        <translation>number=%1 ist keine Werkzeugnummer.</translation>
    </message>
    <message>
        <source>this tool line has no number=…; Toffee needs the T number.</source>
        <translation>diese Werkzeugzeile hat kein number=…; Toffee braucht die T-Nummer.</translation>
    </message>
    <message>
        <source>%1 is in this tool line twice (%1=%2 and %1=%3); Toffee will not guess which one is meant.</source>
        <translation>%1 steht zweimal in dieser Werkzeugzeile (%1=%2 und %1=%3); Toffee rät nicht, welcher Wert gemeint ist.</translation>
    </message>
    <message>
        <source>this is not a text program: it holds binary data (a NUL byte), which a G-code program never does.</source>
        <translation>das ist kein Textprogramm: es enthält Binärdaten (ein NUL-Byte), was ein G-Code-Programm nie tut.</translation>
    </message>
    <message>
        <source>the program&apos;s first %1 MB are all comments; Toffee reads the tool header only from the start of a program.</source>
        <translation>die ersten %1 MB des Programms sind nur Kommentare; Toffee liest den Werkzeugkopf nur am Anfang eines Programms.</translation>
    </message>
    <message>
        <source>this program has no Makera CAM tool header (&quot;;@MKR|TOOL|number=…&quot; lines before the program body); there are no tools to import from it.</source>
        <translation>dieses Programm hat keinen Werkzeugkopf von Makera CAM (Zeilen „;@MKR|TOOL|number=…“ vor dem Programm); es gibt keine Werkzeuge daraus zu importieren.</translation>
    </message>
    <message>
        <source>just now</source>
        <translation>gerade eben</translation>
    </message>
    <message>
        <source>%1 min ago</source>
        <translation>vor %1 min</translation>
    </message>
    <message>
        <source>%1 h ago</source>
        <translation>vor %1 h</translation>
    </message>
    <message>
        <source>%1 days ago</source>
        <translation>vor %1 Tagen</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <source>%1 h %2 min</source>
        <translation>%1 h %2 min</translation>
    </message>
    <message>
        <source>a rack is &quot;none&quot;, or tool numbers and ranges such as 1-6 or 1,2,5-8.</source>
        <translation>Ein Magazin ist „none“ oder eine Liste von Werkzeugnummern und Bereichen wie 1-6 oder 1,2,5-8.</translation>
    </message>
    <message>
        <source>the job check finds %1; the first, on line %2: %3 Fix them before preparing the program (Check Job, or toffee-cli job check, lists them). Nothing was written.</source>
        <translation>Die Jobprüfung findet %1; der erste, in Zeile %2: %3 Beheben Sie die Fehler, bevor Sie das Programm vorbereiten („Job prüfen“ oder toffee-cli job check listet sie auf). Es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>an error</source>
        <translation>einen Fehler</translation>
    </message>
    <message>
        <source>%1 errors</source>
        <translation>%1 Fehler</translation>
    </message>
    <message>
        <source>Preparing was cancelled; nothing was written.</source>
        <translation>Die Vorbereitung wurde abgebrochen; es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Say where the prepared program goes: no file name was given.</source>
        <translation>Geben Sie an, wohin das vorbereitete Programm soll: Es wurde kein Dateiname angegeben.</translation>
    </message>
    <message>
        <source>%1: the prepared program must go to another file than the program itself.</source>
        <translation>%1: Das vorbereitete Programm muss in eine andere Datei als das Programm selbst.</translation>
    </message>
    <message>
        <source>%1 is the tool table: the prepared program must go to another file.</source>
        <translation>%1 ist die Werkzeugtabelle: Das vorbereitete Programm muss in eine andere Datei.</translation>
    </message>
    <message>
        <source>T%1 is not in the table: it is measured at its change.</source>
        <translation>T%1 steht nicht in der Tabelle: Es wird beim Wechsel vermessen.</translation>
    </message>
    <message>
        <source>T%1 has no stored TLO: it is measured at its change.</source>
        <translation>T%1 hat keine gespeicherte TLO: Es wird beim Wechsel vermessen.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was set by hand, not measured: it is measured at its change.</source>
        <translation>Die TLO von T%1 wurde von Hand gesetzt, nicht gemessen: Es wird beim Wechsel vermessen.</translation>
    </message>
    <message>
        <source>T%1 failed its last break test: it is measured at its change.</source>
        <translation>T%1 hat seinen letzten Bruchtest nicht bestanden: Es wird beim Wechsel vermessen.</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO is older than the stale limit (%2 d): it is measured at its change.</source>
        <translation>Die gespeicherte TLO von T%1 ist veraltet (Grenze %2 d): T%1 wird beim Wechsel vermessen.</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO was measured against reference MCS Z %2, but the machine&apos;s is %3: it is measured at its change.</source>
        <translation>Die gespeicherte TLO von T%1 wurde gegen Referenz-MCS-Z %2 gemessen, die der Maschine ist aber %3: T%1 wird beim Wechsel vermessen.</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO does not say which reference it was measured against: it is measured at its change.</source>
        <translation>Bei der gespeicherten TLO von T%1 ist nicht vermerkt, gegen welche Referenz sie gemessen wurde: T%1 wird beim Wechsel vermessen.</translation>
    </message>
    <message>
        <source>Toffee&apos;s zip reader %1 is missing, so .tools archives cannot be read; reinstall Toffee.</source>
        <translation>Toffees Zip-Leser %1 fehlt, deshalb können .tools-Archive nicht gelesen werden; installieren Sie Toffee neu.</translation>
    </message>
    <message>
        <source>Toffee&apos;s zip reader %1 cannot be loaded (%2); reinstall Toffee.</source>
        <translation>Toffees Zip-Leser %1 kann nicht geladen werden (%2); installieren Sie Toffee neu.</translation>
    </message>
    <message>
        <source>column %1: %2</source>
        <translation>Spalte %1: %2</translation>
    </message>
    <message>
        <source>this is not valid JSON: there is more text after the value.</source>
        <translation>Das ist kein gültiges JSON: Nach dem Wert folgt weiterer Text.</translation>
    </message>
    <message>
        <source>this is not valid JSON: there is more text after the library.</source>
        <translation>Das ist kein gültiges JSON: Nach der Bibliothek folgt weiterer Text.</translation>
    </message>
    <message>
        <source>the machine reports no reference (an uncalibrated reference of 0, or a firmware that does not say), so T%1&apos;s stored TLO cannot be checked against it: it is measured at its change.</source>
        <translation>die Maschine meldet keine Referenz (eine unkalibrierte Referenz von 0 oder eine Firmware, die sie nicht nennt), daher kann die gespeicherte Längenkorrektur von T%1 nicht mit ihr geprüft werden: T%1 wird beim Wechsel vermessen.</translation>
    </message>
    <message>
        <source>T%1 is not break-tested: the firmware&apos;s break test takes T0 and every tool from T9 up for its wireless probe, and would halt.</source>
        <translation>T%1 wird nicht auf Bruch geprüft: Der Bruchtest der Firmware nimmt T0 und jedes Werkzeug ab T9 für ihren Funktaster und würde anhalten.</translation>
    </message>
    <message>
        <source>T%1 cannot be written: grblHAL&apos;s G10 L1 needs a tool number from 1 up.</source>
        <translation>T%1 lässt sich nicht schreiben: G10 L1 von grblHAL braucht eine Werkzeugnummer ab 1.</translation>
    </message>
    <message>
        <source>halt reason %1</source>
        <translation>Haltgrund %1</translation>
    </message>
    <message>
        <source>The machine was stopped (Stop, Ctrl-X or the stop button).</source>
        <translation>Die Maschine wurde angehalten (Stopp, Strg-X oder die Stopp-Taste).</translation>
    </message>
    <message>
        <source>Homing failed, or the machine has not been homed.</source>
        <translation>Die Referenzfahrt ist fehlgeschlagen, oder die Maschine wurde nicht referenziert.</translation>
    </message>
    <message>
        <source>The probe did not touch within its safety margin: the tool may be missing, broken or much shorter than expected.</source>
        <translation>Der Taster hat innerhalb seines Sicherheitsabstands nicht ausgelöst: Das Werkzeug fehlt möglicherweise, ist gebrochen oder viel kürzer als erwartet.</translation>
    </message>
    <message>
        <source>Measuring on the tool setter failed: the setter was not touched (the tool may be missing or much shorter than expected), a break test found the tool broken, or the tolerance was too small.</source>
        <translation>Das Vermessen am Werkzeugtaster ist fehlgeschlagen: Der Taster wurde nicht berührt (das Werkzeug fehlt vielleicht oder ist viel kürzer als erwartet), eine Bruchprüfung hat das Werkzeug als gebrochen erkannt, oder die Toleranz war zu klein.</translation>
    </message>
    <message>
        <source>The tool changer could not home.</source>
        <translation>Der Werkzeugwechsler konnte keine Referenzfahrt ausführen.</translation>
    </message>
    <message>
        <source>The tool asked for is not a valid tool.</source>
        <translation>Das angeforderte Werkzeug ist kein gültiges Werkzeug.</translation>
    </message>
    <message>
        <source>The spindle already holds a tool.</source>
        <translation>In der Spindel ist bereits ein Werkzeug.</translation>
    </message>
    <message>
        <source>The spindle overheated.</source>
        <translation>Die Spindel ist überhitzt.</translation>
    </message>
    <message>
        <source>A move went beyond the machine&apos;s travel (soft limit).</source>
        <translation>Eine Bewegung ging über den Verfahrweg der Maschine hinaus (Software-Endschalter).</translation>
    </message>
    <message>
        <source>The cover is open.</source>
        <translation>Die Abdeckung ist offen.</translation>
    </message>
    <message>
        <source>The probe is not valid.</source>
        <translation>Der Taster ist nicht gültig.</translation>
    </message>
    <message>
        <source>The emergency stop is pressed.</source>
        <translation>Der Not-Halt ist gedrückt.</translation>
    </message>
    <message>
        <source>The power supply overheated.</source>
        <translation>Das Netzteil ist überhitzt.</translation>
    </message>
    <message>
        <source>The machine has not been homed.</source>
        <translation>Die Maschine wurde nicht referenziert.</translation>
    </message>
    <message>
        <source>A crash was detected.</source>
        <translation>Eine Kollision wurde erkannt.</translation>
    </message>
    <message>
        <source>The machine halted (reason %1).</source>
        <translation>Die Maschine hat angehalten (Grund %1).</translation>
    </message>
    <message>
        <source>This halt needs a reset of the controller.</source>
        <translation>Dieser Halt erfordert einen Reset der Steuerung.</translation>
    </message>
    <message>
        <source>This halt needs the machine switched off and on again.</source>
        <translation>Dieser Halt erfordert, die Maschine aus- und wieder einzuschalten.</translation>
    </message>
    <message>
        <source>Check the machine, then Unlock ($X).</source>
        <translation>Prüfen Sie die Maschine, dann Entsperren ($X).</translation>
    </message>
    <message>
        <source>The tool setter was never touched: the tool may be missing, broken or much shorter than expected. Check the spindle, then Unlock.</source>
        <translation>Der Werkzeugtaster wurde nie berührt: Das Werkzeug fehlt vielleicht, ist gebrochen oder viel kürzer als erwartet. Prüfen Sie die Spindel, dann Entsperren.</translation>
    </message>
    <message>
        <source>Unlock, home the machine, then try again.</source>
        <translation>Entsperren, die Maschine referenzieren, dann erneut versuchen.</translation>
    </message>
    <message>
        <source>the cutter type is %1 characters long; keep it to %2.</source>
        <translation>der Fräsertyp ist %1 Zeichen lang; höchstens %2 sind erlaubt.</translation>
    </message>
    <message>
        <source>overall length</source>
        <translation>Gesamtlänge</translation>
    </message>
    <message>
        <source>the overall length cannot be negative.</source>
        <translation>die Gesamtlänge kann nicht negativ sein.</translation>
    </message>
    <message>
        <source>a life limit in minutes must be more than 0 and at most %1; leave it empty for none.</source>
        <translation>eine Standzeit in Minuten muss größer als 0 und höchstens %1 sein; leer lassen für keine.</translation>
    </message>
    <message>
        <source>a life limit in uses must be a whole number from 1 to %1; leave it empty for none.</source>
        <translation>eine Standzeit in Einsätzen muss eine ganze Zahl von 1 bis %1 sein; leer lassen für keine.</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no place for tool life limits: they are not saved.</source>
        <translation>Eine LinuxCNC-Tabelle hat keinen Platz für Standzeiten: Sie werden nicht gespeichert.</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no place for the cutter&apos;s type and overall length: they are not saved, and an import can then tell a new cutter only by its diameter.</source>
        <translation>Eine LinuxCNC-Tabelle hat keinen Platz für Typ und Gesamtlänge des Fräsers: Sie werden nicht gespeichert, und ein Import erkennt einen neuen Fräser dann nur an seinem Durchmesser.</translation>
    </message>
    <message>
        <source>dated in the future (%1)</source>
        <translation>in der Zukunft datiert (%1)</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO is dated %2, in the future: a clock was wrong, and when it was measured is not known. It is measured at its change.</source>
        <translation>Die gespeicherte Längenkorrektur von T%1 ist auf %2 datiert, in der Zukunft: Eine Uhr ging falsch, und wann sie gemessen wurde, ist unbekannt. Sie wird beim Wechsel gemessen.</translation>
    </message>
    <message>
        <source>T%1&apos;s %2 event %3 holds a TLO of %4 mm, beyond any tool (%5 mm at most).</source>
        <translation>Das Ereignis %3 (%2) von T%1 enthält eine Längenkorrektur von %4 mm, jenseits jedes Werkzeugs (höchstens %5 mm).</translation>
    </message>
    <message>
        <source>The tool changer found no tool where one should be (an empty rack pocket), or was given no tool.</source>
        <translation>Der Werkzeugwechsler fand kein Werkzeug, wo eines sein sollte (ein leerer Magazinplatz), oder erhielt kein Werkzeug.</translation>
    </message>
    <message>
        <source>&quot;tlo_source&quot; must be &quot;probe&quot;, &quot;manual&quot; or &quot;pulled&quot;.</source>
        <translation>&quot;tlo_source&quot; muss &quot;probe&quot;, &quot;manual&quot; oder &quot;pulled&quot; sein.</translation>
    </message>
    <message>
        <source>tlo_source &quot;%1&quot; must be probe, manual, pulled or empty.</source>
        <translation>tlo_source &quot;%1&quot; muss probe, manual, pulled oder leer sein.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was read from the controller&apos;s table, not measured: it is measured at its change.</source>
        <translation>Die TLO von T%1 wurde aus der Tabelle der Steuerung gelesen, nicht gemessen: T%1 wird beim Wechsel gemessen.</translation>
    </message>
    <message>
        <source>a cutter has 1 to %1 cutting edges; leave it empty when unknown.</source>
        <translation>ein Fräser hat 1 bis %1 Schneiden; leer lassen, wenn unbekannt.</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no place for how a tool is probed (its edges, touches, touch-off point, latch feed and spread limit): they are not saved, and each tool is then probed once at the setter&apos;s centre.</source>
        <translation>Eine LinuxCNC-Tabelle hat keinen Platz dafür, wie ein Werkzeug angetastet wird (Schneiden, Antastungen, Antastpunkt, Feinvorschub und Streuungsgrenze): Das wird nicht gespeichert, und jedes Werkzeug wird dann einmal in der Mitte des Längenmessgeräts angetastet.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be true or false.</source>
        <translation>„%1“ muss true oder false sein.</translation>
    </message>
    <message>
        <source>unknown column &quot;%1&quot; in the header; the columns are %2.</source>
        <translation>unbekannte Spalte „%1“ in der Kopfzeile; die Spalten sind %2.</translation>
    </message>
    <message>
        <source>probe_turn &quot;%1&quot; must be yes, no or empty.</source>
        <translation>probe_turn „%1“ muss yes, no oder leer sein.</translation>
    </message>
</context>
<context>
    <name>Toffee::About</name>
    <message>
        <source>About Toffee</source>
        <translation>Über Toffee</translation>
    </message>
    <message>
        <source>Toffee %1</source>
        <translation>Toffee %1</translation>
    </message>
    <message>
        <source>The tool offset manager: a CNC machine&apos;s tool table and tool length offsets, kept right.

Licensed under the GNU General Public License, version 3 or later.</source>
        <translation>Der Werkzeugkorrektur-Verwalter: Werkzeugtabelle und Werkzeuglängenkorrekturen einer CNC-Maschine, richtig gehalten.

Lizenziert unter der GNU General Public License, Version 3 oder später.</translation>
    </message>
</context>
<context>
    <name>Toffee::AddToolCommand</name>
    <message>
        <source>Add tool T%1</source>
        <translation>Werkzeug T%1 hinzufügen</translation>
    </message>
</context>
<context>
    <name>Toffee::AutoSave</name>
    <message>
        <source>Cannot create the folder for unsaved edits, %1.</source>
        <translation>Der Ordner für ungesicherte Änderungen, %1, kann nicht angelegt werden.</translation>
    </message>
    <message>
        <source>Cannot write in the folder for unsaved edits, %1.</source>
        <translation>In den Ordner für ungesicherte Änderungen, %1, kann nicht geschrieben werden.</translation>
    </message>
</context>
<context>
    <name>Toffee::BreakTestPanel</name>
    <message>
        <source>Run Break Test</source>
        <translation>Bruchtest starten</translation>
    </message>
    <message>
        <source>Break-test tolerance in millimetres</source>
        <translation>Toleranz des Bruchtests in Millimetern</translation>
    </message>
    <message>
        <source>How far the new measurement may differ from the stored TLO; at least %1 mm, %2 mm by default.</source>
        <translation>Wie weit die neue Messung von der gespeicherten Längenkorrektur abweichen darf; mindestens %1 mm, standardmäßig %2 mm.</translation>
    </message>
    <message>
        <source>Run the tool break test</source>
        <translation>Werkzeugbruchtest starten</translation>
    </message>
    <message>
        <source>Re-measure the tool and compare it with its stored TLO (M491.1) — F6</source>
        <translation>Werkzeug neu messen und mit der gespeicherten Längenkorrektur vergleichen (M491.1) — F6</translation>
    </message>
    <message>
        <source>Tolerance:</source>
        <translation>Toleranz:</translation>
    </message>
    <message>
        <source>Stored TLO:</source>
        <translation>Gespeicherte TLO:</translation>
    </message>
    <message>
        <source>Measured TLO:</source>
        <translation>Gemessene TLO:</translation>
    </message>
    <message>
        <source>Difference:</source>
        <translation>Abweichung:</translation>
    </message>
    <message>
        <source>BROKEN TOOL</source>
        <translation>WERKZEUGBRUCH</translation>
    </message>
    <message>
        <source>The break test did not run</source>
        <translation>Der Bruchtest ist nicht gelaufen</translation>
    </message>
    <message>
        <source>Broken tool</source>
        <translation>Werkzeugbruch</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>Entsperren</translation>
    </message>
    <message>
        <source>Leave Halted</source>
        <translation>Angehalten lassen</translation>
    </message>
    <message>
        <source>The machine reports no tool in the spindle.</source>
        <translation>Die Maschine meldet kein Werkzeug in der Spindel.</translation>
    </message>
    <message>
        <source>T%1 has no TLO in the table: the test compares against whatever TLO the machine holds%2, which may not be T%1&apos;s.</source>
        <translation>T%1 hat keine TLO in der Tabelle: Der Test vergleicht mit der TLO, die die Maschine gerade hat%2, und die ist vielleicht nicht die von T%1.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was set by hand (%3), not measured: if that value is not the tool&apos;s real length, the test reports the tool broken and halts the machine.</source>
        <translation>Die TLO %2 von T%1 wurde von Hand gesetzt (%3), nicht gemessen: Entspricht dieser Wert nicht der tatsächlichen Länge des Werkzeugs, meldet der Test das Werkzeug als gebrochen und hält die Maschine an.</translation>
    </message>
    <message>
        <source>Break-test %1?</source>
        <translation>Bruchtest für %1?</translation>
    </message>
    <message>
        <source>The machine will move to the tool setter and measure %1 again, then compare it with its TLO (tolerance %2). Keep hands clear.</source>
        <translation>Die Maschine fährt zum Werkzeugtaster, misst %1 erneut und vergleicht das Ergebnis mit der TLO (Toleranz %2). Halten Sie die Hände fern.</translation>
    </message>
    <message>
        <source>The tool</source>
        <translation>Das Werkzeug</translation>
    </message>
    <message>
        <source>%1 may be broken. The machine has halted, and the table marks %1 until it is probed again.</source>
        <translation>%1 ist möglicherweise gebrochen. Die Maschine hat angehalten, und die Tabelle markiert %1, bis es erneut vermessen wird.</translation>
    </message>
    <message>
        <source>T%1: BROKEN TOOL</source>
        <translation>T%1: WERKZEUG GEBROCHEN</translation>
    </message>
    <message>
        <source>T%1 OK: within %2.</source>
        <translation>T%1 in Ordnung: innerhalb %2.</translation>
    </message>
    <message>
        <source>Tool OK: within %1.</source>
        <translation>Werkzeug in Ordnung: innerhalb %1.</translation>
    </message>
    <message>
        <source>The TLO it was compared against was set by hand, not measured: if that value was not the tool&apos;s real length, the tool may be whole. Look at the tool before you replace it, then probe it.</source>
        <translation>Die TLO, mit der verglichen wurde, war von Hand gesetzt, nicht gemessen: Entsprach dieser Wert nicht der wirklichen Länge des Werkzeugs, ist das Werkzeug womöglich heil. Sehen Sie sich das Werkzeug an, bevor Sie es ersetzen, und vermessen Sie es dann.</translation>
    </message>
    <message>
        <source>The spindle is empty: load a tool first (Rack ▸ Load).</source>
        <translation>Die Spindel ist leer: Wechseln Sie zuerst ein Werkzeug ein (Magazin ▸ Einwechseln).</translation>
    </message>
    <message>
        <source>The machine holds TLO %1 but the table holds %2 for T%3: Toffee sets the table&apos;s %2 first, and the machine compares the tool with it.</source>
        <translation>Die Maschine hat die Längenkorrektur %1, die Tabelle aber %2 für T%3: Toffee setzt zuerst %2 aus der Tabelle, und die Maschine vergleicht das Werkzeug damit.</translation>
    </message>
    <message>
        <source>%1 may be broken. The machine is stopped and lifted (not halted), and the table marks %1 until it is probed again.</source>
        <translation>%1 ist möglicherweise gebrochen. Die Maschine ist gestoppt und angehoben (nicht angehalten), und die Tabelle markiert %1, bis es erneut gemessen wird.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was read from the controller&apos;s table (%3), not measured: if that value is not the tool&apos;s real length, the test reports the tool broken.</source>
        <translation>Die TLO %2 von T%1 wurde aus der Tabelle der Steuerung gelesen (%3), nicht gemessen: Ist dieser Wert nicht die wirkliche Länge des Werkzeugs, meldet der Test das Werkzeug als gebrochen.</translation>
    </message>
</context>
<context>
    <name>Toffee::CarveraConsole</name>
    <message>
        <source>%1 probes the tool: the machine moves to the tool setter, and the TLO it measures is recorded in the table.</source>
        <translation>%1 vermisst das Werkzeug: Die Maschine fährt zum Werkzeugtaster, und die gemessene TLO wird in der Tabelle gespeichert.</translation>
    </message>
    <message>
        <source>The Carvera works in millimetres only: G20 (inches) halts it. Use G21.</source>
        <translation>Die Carvera arbeitet nur in Millimetern: G20 (Zoll) lässt sie anhalten. Verwenden Sie G21.</translation>
    </message>
    <message>
        <source>M491.1 runs a break test: the machine moves to the tool setter and probes the tool. Use Machine ▸ Break Test to have the result recorded in the table.</source>
        <translation>M491.1 führt einen Bruchtest aus: Die Maschine fährt zum Werkzeugtaster und vermisst das Werkzeug. Verwenden Sie Maschine ▸ Bruchtest, damit das Ergebnis in der Tabelle gespeichert wird.</translation>
    </message>
    <message>
        <source>M493.3 needs Z (the TLO) or H (the tool tip&apos;s height above Z0).</source>
        <translation>M493.3 braucht Z (die TLO) oder H (die Höhe der Werkzeugspitze über Z0).</translation>
    </message>
    <message>
        <source>Typed, M493.3 H can set a TLO more than 100 mm off: after an M493.3 Z the community firmware measures H from the TLO instead of the tool&apos;s height. Under &quot;Set the offset by hand&quot;, choose Gauge height above Z0: Toffee works the TLO out from the position and sends it as M493.3 Z.</source>
        <translation>Von Hand eingegeben kann M493.3 H eine Längenkorrektur setzen, die um mehr als 100 mm falsch ist: Nach einem M493.3 Z misst die Community-Firmware H von der Längenkorrektur statt von der Höhe des Werkzeugs. Wählen Sie unter „Korrektur von Hand setzen“ „Lehrenhöhe über Z0“: Toffee berechnet die Längenkorrektur aus der Position und sendet sie als M493.3 Z.</translation>
    </message>
    <message>
        <source>The tool length offset</source>
        <translation>Die Werkzeuglängenkorrektur</translation>
    </message>
    <message>
        <source>%1 changes the tool length offset the next cut uses. The table records it as set by hand.</source>
        <translation>%1 ändert die Werkzeuglängenkorrektur, die der nächste Schnitt verwendet. Die Tabelle speichert sie als von Hand gesetzt.</translation>
    </message>
    <message>
        <source>M493.2 needs a tool (M493.2 T2): without one the machine halts.</source>
        <translation>M493.2 braucht ein Werkzeug (M493.2 T2): Ohne Werkzeug hält die Maschine an.</translation>
    </message>
    <message>
        <source>M493.2 makes T%1 the active tool but keeps the TLO in force now (another tool&apos;s, or none): T%1&apos;s own is not set. Probe T%1 or restore its TLO before cutting.</source>
        <translation>M493.2 macht T%1 zum aktiven Werkzeug, behält aber die jetzt wirksame TL (die eines anderen Werkzeugs oder keine): Die eigene von T%1 ist nicht gesetzt. Vermessen Sie T%1 oder stellen Sie seine TL wieder her, bevor Sie schneiden.</translation>
    </message>
    <message>
        <source>M6 T%1 changes the tool: the machine moves, and then probes T%1 on the tool setter.</source>
        <translation>M6 T%1 wechselt das Werkzeug: Die Maschine fährt und vermisst dann T%1 am Werkzeugtaster.</translation>
    </message>
</context>
<context>
    <name>Toffee::ConflictDialog</name>
    <message>
        <source>not measured</source>
        <translation>nicht gemessen</translation>
    </message>
    <message>
        <source>set by hand</source>
        <translation>von Hand gesetzt</translation>
    </message>
    <message>
        <source>probed</source>
        <translation>vermessen</translation>
    </message>
    <message>
        <source>time unknown</source>
        <translation>Zeit unbekannt</translation>
    </message>
    <message>
        <source>%1 (%2, %3)</source>
        <translation>%1 (%2, %3)</translation>
    </message>
    <message>
        <source>Removed from the table</source>
        <translation>Aus der Tabelle entfernt</translation>
    </message>
    <message>
        <source>Tools changed on another station</source>
        <translation>Auf einer anderen Station geänderte Werkzeuge</translation>
    </message>
    <message>
        <source>Changed on Another Station</source>
        <translation>Auf einer anderen Station geändert</translation>
    </message>
    <message>
        <source>What happened</source>
        <translation>Was passiert ist</translation>
    </message>
    <message>
        <source>Another station changed this tool since you opened the table, and so did you. Choose which version the library keeps. Everything else is saved.</source>
        <translation>Eine andere Station hat dieses Werkzeug geändert, seit Sie die Tabelle geöffnet haben, und Sie ebenfalls. Wählen Sie, welche Version die Bibliothek behält. Alles andere ist gespeichert.</translation>
    </message>
    <message>
        <source>Another station changed these %1 tools since you opened the table, and so did you. Choose, for each, which version the library keeps. Everything else is saved.</source>
        <translation>Eine andere Station hat diese %1 Werkzeuge geändert, seit Sie die Tabelle geöffnet haben, und Sie ebenfalls. Wählen Sie für jedes, welche Version die Bibliothek behält. Alles andere ist gespeichert.</translation>
    </message>
    <message>
        <source>Their version and yours, per tool</source>
        <translation>Die Version der anderen Station und Ihre, je Werkzeug</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>Theirs</source>
        <translation>Ihre</translation>
    </message>
    <message>
        <source>Mine</source>
        <translation>Meine</translation>
    </message>
    <message>
        <source>Keep</source>
        <translation>Behalten</translation>
    </message>
    <message>
        <source>Apply the choices or decide later</source>
        <translation>Die Auswahl anwenden oder später entscheiden</translation>
    </message>
    <message>
        <source>&amp;Apply Choices</source>
        <translation>Auswahl &amp;anwenden</translation>
    </message>
    <message>
        <source>Apply the choices</source>
        <translation>Die Auswahl anwenden</translation>
    </message>
    <message>
        <source>Decide &amp;Later</source>
        <translation>&amp;Später entscheiden</translation>
    </message>
    <message>
        <source>Decide later; your edits stay unsaved</source>
        <translation>Später entscheiden; Ihre Änderungen bleiben ungespeichert</translation>
    </message>
    <message>
        <source>another station</source>
        <translation>einer anderen Station</translation>
    </message>
    <message>
        <source>From %1:</source>
        <translation>Von %1:</translation>
    </message>
    <message>
        <source>From this station:</source>
        <translation>Von dieser Station:</translation>
    </message>
    <message>
        <source>Version of T%1 to keep</source>
        <translation>Zu behaltende Version von T%1</translation>
    </message>
    <message>
        <source>Keep mine</source>
        <translation>Meine behalten</translation>
    </message>
    <message>
        <source>Take theirs (%1)</source>
        <translation>Ihre übernehmen (von %1)</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keine)</translation>
    </message>
    <message>
        <source>Pocket</source>
        <translation>Platz</translation>
    </message>
    <message>
        <source>TLO</source>
        <translation>TLO</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Length wear</source>
        <translation>Längenverschleiß</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <source>Radius wear</source>
        <translation>Radiusverschleiß</translation>
    </message>
    <message>
        <source>Break test</source>
        <translation>Bruchtest</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>fehlgeschlagen</translation>
    </message>
    <message>
        <source>passed or not run</source>
        <translation>bestanden oder nicht ausgeführt</translation>
    </message>
    <message>
        <source>Reference MCS Z</source>
        <translation>Referenz-MCS-Z</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notizen</translation>
    </message>
    <message>
        <source>LinuxCNC fields</source>
        <translation>LinuxCNC-Felder</translation>
    </message>
    <message>
        <source>read from the controller</source>
        <translation>aus der Steuerung gelesen</translation>
    </message>
</context>
<context>
    <name>Toffee::ConnectionPanel</name>
    <message>
        <source>Refresh</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <source>Machine port</source>
        <translation>Maschinenanschluss</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>Baudrate</translation>
    </message>
    <message>
        <source>Refresh the list of ports</source>
        <translation>Liste der Anschlüsse aktualisieren</translation>
    </message>
    <message>
        <source>Built-in emulator</source>
        <translation>Eingebauter Emulator</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>Verbinde …</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <source>Toffee&apos;s own Carvera, for trying things out</source>
        <translation>Toffees eigene Carvera, zum Ausprobieren</translation>
    </message>
    <message>
        <source>How to reach the machine</source>
        <translation>Wie die Maschine erreicht wird</translation>
    </message>
    <message>
        <source>Serial port (USB)</source>
        <translation>Serieller Anschluss (USB)</translation>
    </message>
    <message>
        <source>Wi-Fi</source>
        <translation>WLAN</translation>
    </message>
    <message>
        <source>Machine on the network</source>
        <translation>Maschine im Netzwerk</translation>
    </message>
    <message>
        <source>Address, such as 192.168.1.57</source>
        <translation>Adresse, etwa 192.168.1.57</translation>
    </message>
    <message>
        <source>%1 — %2 (busy)</source>
        <translation>%1 — %2 (belegt)</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>Cannot connect to the machine</source>
        <translation>Keine Verbindung zur Maschine möglich</translation>
    </message>
    <message>
        <source>No machine chosen. Choose one of the machines heard on the network, or type the machine&apos;s address as its screen shows it (such as 192.168.1.57).</source>
        <translation>Keine Maschine gewählt. Wählen Sie eine der im Netzwerk gehörten Maschinen, oder geben Sie die Adresse der Maschine so ein, wie ihr Bildschirm sie zeigt (etwa 192.168.1.57).</translation>
    </message>
    <message>
        <source>The machine is busy</source>
        <translation>Die Maschine ist beschäftigt</translation>
    </message>
    <message>
        <source>%1 says it is busy: another program is connected to it (Makera&apos;s controller, a phone, another computer).</source>
        <translation>%1 meldet sich als belegt: Ein anderes Programm ist mit ihr verbunden (Makeras Controller, ein Telefon, ein anderer Computer).</translation>
    </message>
    <message>
        <source>Commands from two programs at once can interfere, and each sees the other&apos;s replies. Disconnect the other program first, or connect anyway.</source>
        <translation>Befehle aus zwei Programmen zugleich können sich stören, und jedes sieht die Antworten des anderen. Trennen Sie zuerst das andere Programm, oder verbinden Sie sich trotzdem.</translation>
    </message>
    <message>
        <source>Connect Anyway</source>
        <translation>Trotzdem verbinden</translation>
    </message>
    <message>
        <source>Cannot listen for machines on UDP port %1 (%2): type the machine&apos;s address.</source>
        <translation>Auf UDP-Port %1 kann nicht nach Maschinen gehorcht werden (%2): Geben Sie die Adresse der Maschine ein.</translation>
    </message>
    <message>
        <source>%1 is busy: another program is connected to it.</source>
        <translation>%1 ist belegt: Ein anderes Programm ist mit ihr verbunden.</translation>
    </message>
    <message>
        <source>Listening for machines on the network… None heard yet: a Carvera announces itself once a second when its Wi-Fi is on. Or type its address.</source>
        <translation>Horche auf Maschinen im Netzwerk… Noch keine gehört: Eine Carvera meldet sich einmal pro Sekunde, wenn ihr WLAN an ist. Oder geben Sie ihre Adresse ein.</translation>
    </message>
    <message>
        <source>One machine heard on the network.</source>
        <translation>Eine Maschine im Netzwerk gehört.</translation>
    </message>
    <message>
        <source>%1 machines heard on the network.</source>
        <translation>%1 Maschinen im Netzwerk gehört.</translation>
    </message>
    <message>
        <source>Controller the machine runs</source>
        <translation>Steuerung, mit der die Maschine läuft</translation>
    </message>
    <message>
        <source>%1 announcements were not listed: a device announced many names (a flood, or a misbehaving device). Every machine announcing itself from its own address is listed.</source>
        <translation>%1 Ankündigungen wurden nicht aufgeführt: Ein Gerät hat viele Namen angekündigt (eine Flut oder ein fehlerhaftes Gerät). Jede Maschine, die sich von ihrer eigenen Adresse ankündigt, wird aufgeführt.</translation>
    </message>
    <message>
        <source>Which controller the machine runs. Automatic asks it with questions that change nothing on a Carvera or on grblHAL; a controller chosen is checked all the same.</source>
        <translation>Welche Steuerung die Maschine hat. Automatisch fragt sie mit Fragen, die an einer Carvera und an grblHAL nichts ändern; eine gewählte Steuerung wird trotzdem geprüft.</translation>
    </message>
    <message>
        <source>Automatic: %1</source>
        <translation>Automatisch: %1</translation>
    </message>
</context>
<context>
    <name>Toffee::ConsoleCheck</name>
    <message>
        <source>The machine is halted: only Unlock ($X) runs now. Check the machine, then use Machine ▸ Unlock.</source>
        <translation>Die Maschine ist angehalten: Jetzt läuft nur Entsperren ($X). Prüfen Sie die Maschine und verwenden Sie dann Maschine ▸ Entsperren.</translation>
    </message>
    <message>
        <source>$H homes the machine: every axis moves to its limit switch.</source>
        <translation>$H führt die Referenzfahrt aus: Jede Achse fährt an ihren Endschalter.</translation>
    </message>
    <message>
        <source>%1 jogs the machine.</source>
        <translation>%1 verfährt die Maschine im Tippbetrieb.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a G-code line Toffee can read; check it for a letter without a number.</source>
        <translation>„%1“ ist keine G-Code-Zeile, die Toffee lesen kann; prüfen Sie, ob darin ein Buchstabe ohne Zahl steht.</translation>
    </message>
    <message>
        <source>The machine is halted: it refuses &quot;%1&quot; until it is unlocked. Check the machine, then use Machine ▸ Unlock ($X).</source>
        <translation>Die Maschine ist angehalten: Sie lehnt „%1“ ab, bis sie entsperrt ist. Prüfen Sie die Maschine und verwenden Sie dann Maschine ▸ Entsperren ($X).</translation>
    </message>
    <message>
        <source>M6 needs a tool (M6 T2).</source>
        <translation>M6 braucht ein Werkzeug (M6 T2).</translation>
    </message>
    <message>
        <source>%1 starts the spindle.</source>
        <translation>%1 startet die Spindel.</translation>
    </message>
    <message>
        <source>%1 moves the machine.</source>
        <translation>%1 bewegt die Maschine.</translation>
    </message>
    <message>
        <source>Toffee asks the machine for its status several times a second: the strip at the top shows it.</source>
        <translation>Toffee fragt den Zustand der Maschine mehrmals pro Sekunde ab: Die Leiste oben zeigt ihn.</translation>
    </message>
    <message>
        <source>%1 is not a tool number; use %2 to %3 (%4 for an empty spindle).</source>
        <translation>%1 ist keine Werkzeugnummer; verwenden Sie %2 bis %3 (%4 für eine leere Spindel).</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a G-code line Toffee can read: %2</source>
        <translation>„%1“ ist keine G-Code-Zeile, die Toffee lesen kann: %2</translation>
    </message>
    <message>
        <source>%1 writes an offset into the controller (a tool&apos;s length or a work offset); nothing moves, but the next moves use it.</source>
        <translation>%1 schreibt einen Versatz in die Steuerung (eine Werkzeuglänge oder einen Nullpunkt); nichts bewegt sich, aber die nächsten Bewegungen verwenden ihn.</translation>
    </message>
    <message>
        <source>%1 shifts the work coordinates; nothing moves, but the next moves use them.</source>
        <translation>%1 verschiebt die Werkstückkoordinaten; nichts bewegt sich, aber die nächsten Bewegungen verwenden sie.</translation>
    </message>
    <message>
        <source>%1 sets the tool length offset in force; nothing moves, but the next moves use it.</source>
        <translation>%1 setzt den wirksamen Werkzeuglängenversatz; nichts bewegt sich, aber die nächsten Bewegungen verwenden ihn.</translation>
    </message>
    <message>
        <source>Toffee works in millimetres: after G20 the controller would read every later line in inches while Toffee shows millimetres. Use G21.</source>
        <translation>Toffee arbeitet in Millimetern: Nach G20 würde die Steuerung jede weitere Zeile in Zoll lesen, während Toffee Millimeter zeigt. Verwenden Sie G21.</translation>
    </message>
    <message>
        <source>M6 T%1 changes the tool.</source>
        <translation>M6 T%1 wechselt das Werkzeug.</translation>
    </message>
</context>
<context>
    <name>Toffee::ConsoleDock</name>
    <message>
        <source>Console</source>
        <translation>Konsole</translation>
    </message>
    <message>
        <source>Lines sent to and received from the machine</source>
        <translation>Zeilen, die an die Maschine gesendet und von ihr empfangen wurden</translation>
    </message>
    <message>
        <source>Filter the console</source>
        <translation>Konsole filtern</translation>
    </message>
    <message>
        <source>Filter…</source>
        <translation>Filtern …</translation>
    </message>
    <message>
        <source>Command to send to the machine</source>
        <translation>Befehl an die Maschine</translation>
    </message>
    <message>
        <source>not connected; connect first</source>
        <translation>nicht verbunden; zuerst verbinden</translation>
    </message>
    <message>
        <source>the machine is busy with %1; wait for it</source>
        <translation>die Maschine ist mit %1 beschäftigt; bitte warten</translation>
    </message>
    <message>
        <source>… (%1 bytes in all)</source>
        <translation>… (insgesamt %1 Byte)</translation>
    </message>
    <message>
        <source>not sent: %1</source>
        <translation>nicht gesendet: %1</translation>
    </message>
    <message>
        <source>Send %1?</source>
        <translation>%1 senden?</translation>
    </message>
    <message>
        <source>Keep hands clear. Send it?</source>
        <translation>Halten Sie die Hände fern. Senden?</translation>
    </message>
    <message>
        <source>not sent: cancelled</source>
        <translation>nicht gesendet: abgebrochen</translation>
    </message>
    <message>
        <source>recorded in the table: T%1 TLO %2, set by hand</source>
        <translation>in der Tabelle gespeichert: T%1 TLO %2, von Hand gesetzt</translation>
    </message>
    <message>
        <source>the TLO is set on the machine but not recorded: %1</source>
        <translation>die TLO ist an der Maschine gesetzt, aber nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>The TLO is %1 now.</source>
        <translation>Die TLO ist jetzt %1.</translation>
    </message>
    <message>
        <source>T%1 is not in the tool table.</source>
        <translation>T%1 steht nicht in der Werkzeugtabelle.</translation>
    </message>
    <message>
        <source>the tool was probed, but its TLO could not be read, so nothing was recorded: %1</source>
        <translation>das Werkzeug wurde vermessen, aber seine TLO war nicht lesbar, daher wurde nichts gespeichert: %1</translation>
    </message>
    <message>
        <source>recorded in the table: T%1 TLO %2, probed</source>
        <translation>in der Tabelle gespeichert: T%1 TLO %2, vermessen</translation>
    </message>
    <message>
        <source>T%1 was probed but not recorded: %2</source>
        <translation>T%1 wurde vermessen, aber nicht gespeichert: %2</translation>
    </message>
    <message>
        <source>Type a command and press Enter; ↑ ↓ for history</source>
        <translation>Befehl eingeben und Enter drücken; ↑ ↓ für den Verlauf</translation>
    </message>
    <message>
        <source>Type a command (e.g. %1) and press Enter; ↑ ↓ for history</source>
        <translation>Befehl eingeben (z. B. %1) und Enter drücken; ↑ ↓ für den Verlauf</translation>
    </message>
</context>
<context>
    <name>Toffee::ControllerDetector</name>
    <message>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>Automatisch</translation>
    </message>
    <message>
        <source>The link to %1 did not open within %2 s. Check the machine and the connection, then try again.</source>
        <translation>Die Verbindung zu %1 wurde nicht innerhalb von %2 s geöffnet. Prüfen Sie die Maschine und die Verbindung und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>%1 The controller was asked which it is (&quot;version&quot;) and did not answer; nothing else was sent.</source>
        <translation>%1 Die Steuerung wurde gefragt, welche sie ist („version“), und hat nicht geantwortet; sonst wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>The controller answered $I as Grbl does but did not say it is grblHAL ([FIRMWARE:grblHAL]): it may be classic Grbl, which keeps no tool table. Toffee manages Carvera and grblHAL machines; nothing else was sent.</source>
        <translation>Die Steuerung hat $I wie Grbl beantwortet, aber nicht gesagt, dass sie grblHAL ist ([FIRMWARE:grblHAL]): Es kann das klassische Grbl sein, das keine Werkzeugtabelle führt. Toffee verwaltet Carvera- und grblHAL-Maschinen; sonst wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>The controller is not a Carvera, grblHAL or LinuxCNC, the controllers Toffee manages: it answered &quot;version&quot; with %1 and &quot;$I&quot; with %2. Nothing else was sent. If it is one of them, choose it (Carvera, grblHAL or LinuxCNC; toffee-cli --controller) and connect again.</source>
        <translation>Die Steuerung ist weder eine Carvera noch grblHAL noch LinuxCNC, die Steuerungen, die Toffee verwaltet: Sie beantwortete „version“ mit %1 und „$I“ mit %2. Sonst wurde nichts gesendet. Ist sie doch eine davon, wählen Sie sie aus (Carvera, grblHAL oder LinuxCNC; toffee-cli --controller) und verbinden Sie erneut.</translation>
    </message>
    <message>
        <source>%1 The machine answered nothing: not to the Carvera&apos;s and grblHAL&apos;s first question, nor to LinuxCNC&apos;s hello. Check that it is switched on and has started, and the address and port.</source>
        <translation>%1 Die Maschine antwortete gar nicht: weder auf die erste Frage von Carvera und grblHAL noch auf das hello von LinuxCNC. Prüfen Sie, ob sie eingeschaltet und hochgefahren ist, sowie Adresse und Port.</translation>
    </message>
    <message>
        <source>The controller is none of those Toffee manages: it answered LinuxCNC&apos;s hello with %1. Nothing else was sent.</source>
        <translation>Die Steuerung ist keine derer, die Toffee verwaltet: Sie beantwortete das hello von LinuxCNC mit %1. Sonst wurde nichts gesendet.</translation>
    </message>
</context>
<context>
    <name>Toffee::EditToolCommand</name>
    <message>
        <source>Edit tool T%1</source>
        <translation>Werkzeug T%1 bearbeiten</translation>
    </message>
</context>
<context>
    <name>Toffee::EmulatorTransport</name>
    <message>
        <source>The link to the emulator dropped.</source>
        <translation>Die Verbindung zum Emulator ist abgebrochen.</translation>
    </message>
    <message>
        <source>The link to the emulator is not open.</source>
        <translation>Die Verbindung zum Emulator ist nicht offen.</translation>
    </message>
    <message>
        <source>built-in emulator</source>
        <translation>eingebauter Emulator</translation>
    </message>
</context>
<context>
    <name>Toffee::Error</name>
    <message>
        <source>line %1: %2</source>
        <translation>Zeile %1: %2</translation>
    </message>
</context>
<context>
    <name>Toffee::ExportDialog</name>
    <message>
        <source>Save…</source>
        <translation>Speichern …</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Kopieren</translation>
    </message>
    <message>
        <source>Export for Controller</source>
        <translation>Für Steuerung exportieren</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Steuerung</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>All tools</source>
        <translation>Alle Werkzeuge</translation>
    </message>
    <message>
        <source>The program that will be written</source>
        <translation>Das Programm, das geschrieben wird</translation>
    </message>
    <message>
        <source>Controller:</source>
        <translation>Steuerung:</translation>
    </message>
    <message>
        <source>Tool:</source>
        <translation>Werkzeug:</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation>Export nicht möglich</translation>
    </message>
    <message>
        <source>Save the Offset Program</source>
        <translation>Korrekturprogramm speichern</translation>
    </message>
    <message>
        <source>G-code programs (*.nc *.ngc *.gcode *.pgm);;All files (*)</source>
        <translation>G-Code-Programme (*.nc *.ngc *.gcode *.pgm);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>Toffee::FirmwareInfo</name>
    <message>
        <source>Community firmware %1</source>
        <translation>Community-Firmware %1</translation>
    </message>
    <message>
        <source>Makera stock firmware %1</source>
        <translation>Makera-Originalfirmware %1</translation>
    </message>
    <message>
        <source>grblHAL %1</source>
        <translation>grblHAL %1</translation>
    </message>
    <message>
        <source>Unknown firmware (it did not answer &quot;version&quot;)</source>
        <translation>Unbekannte Firmware (sie hat auf „version“ nicht geantwortet)</translation>
    </message>
    <message>
        <source>Unknown firmware %1</source>
        <translation>Unbekannte Firmware %1</translation>
    </message>
    <message>
        <source>LinuxCNC %1</source>
        <translation>LinuxCNC %1</translation>
    </message>
</context>
<context>
    <name>Toffee::FusionToolReader</name>
    <message>
        <source>&quot;%1&quot; is %2, not an object.</source>
        <translation>„%1“ ist %2, kein Objekt.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is %2, not text.</source>
        <translation>„%1“ ist %2, kein Text.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is %2, not a number.</source>
        <translation>„%1“ ist %2, keine Zahl.</translation>
    </message>
    <message>
        <source>it has no &quot;post-process&quot; &quot;number&quot;: Toffee needs the T number the post writes.</source>
        <translation>es hat keine „post-process“-„number“: Toffee braucht die T-Nummer, die der Postprozessor schreibt.</translation>
    </message>
    <message>
        <source>its &quot;number&quot; is %1, not a whole number.</source>
        <translation>seine „number“ ist %1, keine ganze Zahl.</translation>
    </message>
    <message>
        <source>its &quot;length-offset&quot; is %1, not a whole number.</source>
        <translation>sein „length-offset“ ist %1, keine ganze Zahl.</translation>
    </message>
    <message>
        <source>its &quot;number&quot; %1 is out of range; use %2 to %3.</source>
        <translation>seine „number“ %1 liegt außerhalb des Bereichs; verwenden Sie %2 bis %3.</translation>
    </message>
    <message>
        <source>its &quot;unit&quot; is &quot;%1&quot;; Toffee reads millimeters or inches.</source>
        <translation>seine „unit“ ist „%1“; Toffee liest millimeters oder inches.</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; appears twice; Toffee will not guess which one is meant.</source>
        <translation>der Schlüssel „%1“ kommt zweimal vor; Toffee rät nicht, welcher gemeint ist.</translation>
    </message>
</context>
<context>
    <name>Toffee::GCodeInterpreter</name>
    <message>
        <source>&quot;%1&quot; is not G-code this controller reads.</source>
        <translation>„%1“ ist kein G-Code, den diese Steuerung liest.</translation>
    </message>
    <message>
        <source>the word %1 needs a value.</source>
        <translation>Das Wort %1 braucht einen Wert.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number.</source>
        <translation>„%1“ ist keine Zahl.</translation>
    </message>
    <message>
        <source>G%1 is not simulated.</source>
        <translation>G%1 wird nicht simuliert.</translation>
    </message>
    <message>
        <source>on Automation1, G43 is not tool length compensation; use G44 axes, offsets and G143 / G144.</source>
        <translation>Bei Automation1 ist G43 keine Werkzeuglängenkorrektur; verwenden Sie G44-Achsen, Korrekturen und G143 / G144.</translation>
    </message>
    <message>
        <source>G143, G144 and G149 exclude one another.</source>
        <translation>G143, G144 und G149 schließen einander aus.</translation>
    </message>
    <message>
        <source>the Carvera has no G43/G44/G49: its TLO always applies.</source>
        <translation>Die Carvera hat kein G43/G44/G49: ihre Längenkorrektur gilt immer.</translation>
    </message>
    <message>
        <source>PS0030 ILLEGAL OFFSET NUMBER: H%1; offsets go from 0 to %2.</source>
        <translation>PS0030 ILLEGAL OFFSET NUMBER: H%1; Korrekturen gehen von 0 bis %2.</translation>
    </message>
    <message>
        <source>H%1 is not an offset number (0 to %2).</source>
        <translation>H%1 ist keine Korrekturnummer (0 bis %2).</translation>
    </message>
    <message>
        <source>Cannot change tool offset with cutter radius compensation on</source>
        <translation>Cannot change tool offset with cutter radius compensation on (Werkzeugkorrektur bei aktiver Radiuskorrektur nicht änderbar)</translation>
    </message>
    <message>
        <source>M61 needs Q, the tool number.</source>
        <translation>M61 braucht Q, die Werkzeugnummer.</translation>
    </message>
    <message>
        <source>tool %1 is not in the tool table.</source>
        <translation>Werkzeug %1 steht nicht in der Werkzeugtabelle.</translation>
    </message>
    <message>
        <source>G43.1 needs Z, the offset.</source>
        <translation>G43.1 braucht Z, die Korrektur.</translation>
    </message>
    <message>
        <source>G43.2 needs H, the tool whose offset it adds.</source>
        <translation>G43.2 braucht H, das Werkzeug, dessen Korrektur addiert wird.</translation>
    </message>
    <message>
        <source>PS0031 ILLEGAL P COMMAND IN G10: G10 needs an L word.</source>
        <translation>PS0031 ILLEGAL P COMMAND IN G10: G10 braucht ein L-Wort.</translation>
    </message>
    <message>
        <source>G10 needs an L word.</source>
        <translation>G10 braucht ein L-Wort.</translation>
    </message>
    <message>
        <source>G10 L%1 is not simulated for LinuxCNC; G10 L1 writes the tool table.</source>
        <translation>G10 L%1 wird für LinuxCNC nicht simuliert; G10 L1 schreibt die Werkzeugtabelle.</translation>
    </message>
    <message>
        <source>G10 L1 needs P, a tool number in the tool table.</source>
        <translation>G10 L1 braucht P, eine Werkzeugnummer aus der Werkzeugtabelle.</translation>
    </message>
    <message>
        <source>G10 L1: tool %1 is not in the tool table.</source>
        <translation>G10 L1: Werkzeug %1 steht nicht in der Werkzeugtabelle.</translation>
    </message>
    <message>
        <source>this controller&apos;s offset table is not programmed with G10.</source>
        <translation>Die Korrekturtabelle dieser Steuerung wird nicht mit G10 programmiert.</translation>
    </message>
    <message>
        <source>G10 may not be programmed while cutter compensation (G41/G42) is active; nothing was written.</source>
        <translation>G10 darf bei aktiver Fräserradiuskorrektur (G41/G42) nicht programmiert werden; nichts wurde geschrieben.</translation>
    </message>
    <message>
        <source>PS0031 ILLEGAL P COMMAND IN G10: L%1 is not L10 to L13.</source>
        <translation>PS0031 ILLEGAL P COMMAND IN G10: L%1 ist nicht L10 bis L13.</translation>
    </message>
    <message>
        <source>G10 L%1 is not L10 to L13.</source>
        <translation>G10 L%1 ist nicht L10 bis L13.</translation>
    </message>
    <message>
        <source>PS0031 ILLEGAL P COMMAND IN G10: P must be an offset number from 1 to %1.</source>
        <translation>PS0031 ILLEGAL P COMMAND IN G10: P muss eine Korrekturnummer von 1 bis %1 sein.</translation>
    </message>
    <message>
        <source>G10 needs P, an offset number from 1 to %1.</source>
        <translation>G10 braucht P, eine Korrekturnummer von 1 bis %1.</translation>
    </message>
    <message>
        <source>PS0031 ILLEGAL P COMMAND IN G10: the value (R) is missing.</source>
        <translation>PS0031 ILLEGAL P COMMAND IN G10: der Wert (R) fehlt.</translation>
    </message>
    <message>
        <source>G10 needs R, the value.</source>
        <translation>G10 braucht R, den Wert.</translation>
    </message>
    <message>
        <source>PS0032 ILLEGAL OFFSET VALUE IN G10: %1 is beyond ±%2.</source>
        <translation>PS0032 ILLEGAL OFFSET VALUE IN G10: %1 liegt jenseits von ±%2.</translation>
    </message>
    <message>
        <source>G10: %1 is beyond ±%2.</source>
        <translation>G10: %1 liegt jenseits von ±%2.</translation>
    </message>
    <message>
        <source>cutter compensation takes 2 or 3 axes.</source>
        <translation>Die Fräserkorrektur nimmt 2 oder 3 Achsen.</translation>
    </message>
    <message>
        <source>the compensation axes can only change while cutter offset compensation is off.</source>
        <translation>Die Korrekturachsen lassen sich nur bei ausgeschalteter Fräserversatzkorrektur ändern.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a call this simulator knows.</source>
        <translation>„%1“ ist kein Aufruf, den dieser Simulator kennt.</translation>
    </message>
    <message>
        <source>CutterCompensationSetAxes takes axes such as [X, Y, Z].</source>
        <translation>CutterCompensationSetAxes nimmt Achsen wie [X, Y, Z].</translation>
    </message>
    <message>
        <source>CutterCompensationSetOffsets works only while cutter offset compensation is off.</source>
        <translation>CutterCompensationSetOffsets wirkt nur bei ausgeschalteter Fräserversatzkorrektur.</translation>
    </message>
    <message>
        <source>CutterCompensationSetOffsets needs %1 offsets, one for each compensation axis.</source>
        <translation>CutterCompensationSetOffsets braucht %1 Korrekturen, eine je Korrekturachse.</translation>
    </message>
    <message>
        <source>Home takes axes such as X or [X, Y].</source>
        <translation>Home nimmt Achsen wie X oder [X, Y].</translation>
    </message>
    <message>
        <source>%1%2 must be a whole number from %3 to %4.</source>
        <translation>%1%2 muss eine ganze Zahl von %3 bis %4 sein.</translation>
    </message>
    <message>
        <source>too many G codes in one block.</source>
        <translation>Zu viele G-Codes in einem Satz.</translation>
    </message>
    <message>
        <source>too many M codes in one block.</source>
        <translation>Zu viele M-Codes in einem Satz.</translation>
    </message>
    <message>
        <source>the word %1 appears twice in one block.</source>
        <translation>Das Wort %1 kommt in einem Satz zweimal vor.</translation>
    </message>
    <message>
        <source>F%1 is not a feed rate.</source>
        <translation>F%1 ist kein Vorschub.</translation>
    </message>
    <message>
        <source>the arc&apos;s R%1 cannot reach its end point.</source>
        <translation>Der Bogen mit R%1 erreicht seinen Endpunkt nicht.</translation>
    </message>
    <message>
        <source>G%1 needs the arc&apos;s centre (%2 %3) or its radius (R).</source>
        <translation>G%1 braucht den Mittelpunkt des Bogens (%2 %3) oder seinen Radius (R).</translation>
    </message>
    <message>
        <source>G10 L%1 P%2: the work offsets are G54 to G59 (P1 to P6; LinuxCNC&apos;s G59.1 to G59.3 are P7 to P9).</source>
        <translation>G10 L%1 P%2: Die Werkstücknullpunkte sind G54 bis G59 (P1 bis P6; G59.1 bis G59.3 von LinuxCNC sind P7 bis P9).</translation>
    </message>
    <message>
        <source>M%1 calls or ends a subprogram, which the check does not follow: what it cuts is not checked.</source>
        <translation>M%1 ruft ein Unterprogramm auf oder beendet es, und die Prüfung folgt ihm nicht: Was es schneidet, wird nicht geprüft.</translation>
    </message>
    <message>
        <source>canned cycles are simulated in the XY plane (G17) only.</source>
        <translation>Festzyklen werden nur in der XY-Ebene (G17) simuliert.</translation>
    </message>
    <message>
        <source>G%1 needs Z, the bottom of the hole.</source>
        <translation>G%1 braucht Z, den Bohrungsgrund.</translation>
    </message>
</context>
<context>
    <name>Toffee::GCodeLexer</name>
    <message>
        <source>a comment &quot;(&quot; is never closed on this line.</source>
        <translation>Ein Kommentar „(“ wird in dieser Zeile nicht geschlossen.</translation>
    </message>
    <message>
        <source>unexpected &quot;%1&quot;.</source>
        <translation>Unerwartetes „%1“.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number.</source>
        <translation>„%1“ ist keine Zahl.</translation>
    </message>
    <message>
        <source>%1 is too large: a controller takes at most eight digits before the decimal point.</source>
        <translation>%1 ist zu groß: Eine Steuerung nimmt höchstens acht Stellen vor dem Dezimalpunkt.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not G-code this controller reads.</source>
        <translation>„%1“ ist kein G-Code, den diese Steuerung liest.</translation>
    </message>
    <message>
        <source>unexpected byte 0x%1.</source>
        <translation>Unerwartetes Byte 0x%1.</translation>
    </message>
</context>
<context>
    <name>Toffee::GrblHal</name>
    <message>
        <source>A limit switch was hit while moving: the machine stopped at once and may have lost its position. Clear the switch, unlock ($X) and home the machine ($H) before going on.</source>
        <translation>Während der Bewegung wurde ein Endschalter ausgelöst: Die Maschine hat sofort angehalten und ihre Position möglicherweise verloren. Fahren Sie den Endschalter frei, entsperren Sie ($X) und führen Sie eine Referenzfahrt ($H) durch, bevor Sie weiterarbeiten.</translation>
    </message>
    <message>
        <source>A move would have gone beyond the machine&apos;s travel: nothing moved and the position is kept. Unlock ($X) and check the target (for a probe: the setter&apos;s position and the lowest Z to search to).</source>
        <translation>Eine Bewegung hätte den Verfahrweg der Maschine überschritten: Es wurde nichts bewegt, die Position bleibt erhalten. Entsperren Sie ($X) und prüfen Sie das Ziel (bei einer Längenmessung: die Position des Werkzeuglängensensors und die tiefste Z-Position für die Suche).</translation>
    </message>
    <message>
        <source>The controller was reset or stopped while moving: the position may be lost. Unlock ($X) and home the machine ($H) before going on.</source>
        <translation>Die Steuerung wurde während der Bewegung zurückgesetzt oder angehalten: Die Position ist möglicherweise verloren. Entsperren Sie ($X) und führen Sie eine Referenzfahrt ($H) durch, bevor Sie weiterarbeiten.</translation>
    </message>
    <message>
        <source>Probe already touching: the probe input was triggered before the probe moved, so nothing was measured. Unlock ($X), then check that the tool is not resting on the setter and that the setter is clean and wired right.</source>
        <translation>Taster bereits ausgelöst: Der Tastereingang war schon vor der Messbewegung aktiv, daher wurde nichts gemessen. Entsperren Sie ($X) und prüfen Sie dann, dass das Werkzeug nicht auf dem Werkzeuglängensensor aufliegt und dass der Sensor sauber und richtig angeschlossen ist.</translation>
    </message>
    <message>
        <source>Probe found nothing: the tool never touched the setter within the travel allowed, so nothing was measured. Unlock ($X), then check the setter and the tool: the right tool in the spindle, the setter under it, the lowest Z deep enough.</source>
        <translation>Messung ohne Kontakt: Das Werkzeug hat den Werkzeuglängensensor innerhalb des zulässigen Wegs nicht berührt, daher wurde nichts gemessen. Entsperren Sie ($X) und prüfen Sie dann Sensor und Werkzeug: das richtige Werkzeug in der Spindel, der Sensor darunter, die tiefste Z-Position tief genug.</translation>
    </message>
    <message>
        <source>Homing was interrupted by a reset. Unlock ($X) or home the machine again ($H).</source>
        <translation>Die Referenzfahrt wurde durch einen Reset unterbrochen. Entsperren Sie ($X) oder führen Sie die Referenzfahrt erneut durch ($H).</translation>
    </message>
    <message>
        <source>Homing stopped because the safety door was opened. Close the door and home again ($H).</source>
        <translation>Die Referenzfahrt wurde abgebrochen, weil die Schutztür geöffnet wurde. Schließen Sie die Tür und führen Sie die Referenzfahrt erneut durch ($H).</translation>
    </message>
    <message>
        <source>Homing failed: the machine could not move off a limit switch. Check the switch and its wiring (or the pull-off distance), then home again ($H).</source>
        <translation>Referenzfahrt fehlgeschlagen: Die Maschine konnte nicht von einem Endschalter freifahren. Prüfen Sie den Schalter und seine Verdrahtung (oder den Freifahrweg) und führen Sie dann die Referenzfahrt erneut durch ($H).</translation>
    </message>
    <message>
        <source>Homing failed: a limit switch was not found within the search distance. Check the switches and their wiring, then home again ($H).</source>
        <translation>Referenzfahrt fehlgeschlagen: Innerhalb des Suchwegs wurde kein Endschalter gefunden. Prüfen Sie die Schalter und ihre Verdrahtung und führen Sie dann die Referenzfahrt erneut durch ($H).</translation>
    </message>
    <message>
        <source>The emergency stop is engaged. Make the machine safe, release the stop, then reset the controller and unlock ($X).</source>
        <translation>Der Not-Halt ist ausgelöst. Bringen Sie die Maschine in einen sicheren Zustand, entriegeln Sie den Not-Halt, setzen Sie dann die Steuerung zurück und entsperren Sie ($X).</translation>
    </message>
    <message>
        <source>The machine must be homed before it moves: home it ($H).</source>
        <translation>Die Maschine braucht vor jeder Bewegung eine Referenzfahrt: Führen Sie sie durch ($H).</translation>
    </message>
    <message>
        <source>A limit switch is pressed. Unlock ($X), move the machine off the switch, then go on.</source>
        <translation>Ein Endschalter ist betätigt. Entsperren Sie ($X), fahren Sie die Maschine vom Schalter frei und arbeiten Sie dann weiter.</translation>
    </message>
    <message>
        <source>The probe&apos;s protection tripped: the probe was touched while the machine moved. Check the probe, then unlock ($X).</source>
        <translation>Der Tasterschutz hat angesprochen: Der Taster wurde während einer Maschinenbewegung berührt. Prüfen Sie den Taster und entsperren Sie dann ($X).</translation>
    </message>
    <message>
        <source>The spindle did not reach its speed in time. Check the spindle and its drive, then unlock ($X).</source>
        <translation>Die Spindel hat ihre Drehzahl nicht rechtzeitig erreicht. Prüfen Sie die Spindel und ihren Antrieb und entsperren Sie dann ($X).</translation>
    </message>
    <message>
        <source>The controller&apos;s power-on self test failed. Switch the controller off and on; if it happens again, check its wiring.</source>
        <translation>Der Selbsttest der Steuerung beim Einschalten ist fehlgeschlagen. Schalten Sie die Steuerung aus und wieder ein; tritt der Fehler erneut auf, prüfen Sie ihre Verdrahtung.</translation>
    </message>
    <message>
        <source>A motor driver reported a fault. Check the drivers and the motors, then reset the controller.</source>
        <translation>Ein Motortreiber hat einen Fehler gemeldet. Prüfen Sie die Treiber und die Motoren und setzen Sie dann die Steuerung zurück.</translation>
    </message>
    <message>
        <source>Homing failed: the homing settings do not fit the machine. Check them ($$), then home again ($H).</source>
        <translation>Referenzfahrt fehlgeschlagen: Die Einstellungen für die Referenzfahrt passen nicht zur Maschine. Prüfen Sie sie ($$) und führen Sie dann die Referenzfahrt erneut durch ($H).</translation>
    </message>
    <message>
        <source>A Modbus device (often the spindle&apos;s drive) did not answer or answered wrong. Check its cable and settings, then reset the controller.</source>
        <translation>Ein Modbus-Gerät (oft der Spindelantrieb) hat nicht oder fehlerhaft geantwortet. Prüfen Sie sein Kabel und seine Einstellungen und setzen Sie dann die Steuerung zurück.</translation>
    </message>
    <message>
        <source>The controller lost contact with an input/output expander. Check it and its cable, then reset the controller.</source>
        <translation>Die Steuerung hat die Verbindung zu einer Ein-/Ausgangserweiterung verloren. Prüfen Sie die Erweiterung und ihr Kabel und setzen Sie dann die Steuerung zurück.</translation>
    </message>
    <message>
        <source>The controller&apos;s settings memory failed: its settings and tool table may be lost. Check them ($$ and $#) before going on.</source>
        <translation>Der Einstellungsspeicher der Steuerung ist ausgefallen: Einstellungen und Werkzeugtabelle sind möglicherweise verloren. Prüfen Sie sie ($$ und $#), bevor Sie weiterarbeiten.</translation>
    </message>
    <message>
        <source>The controller&apos;s buffer overflowed. Reset the controller and send the work again.</source>
        <translation>Der Puffer der Steuerung ist übergelaufen. Setzen Sie die Steuerung zurück und senden Sie den Auftrag erneut.</translation>
    </message>
    <message>
        <source>The controller halted (ALARM:%1). Make the machine safe, then unlock ($X) or reset the controller; the controller&apos;s documentation says what this alarm means.</source>
        <translation>Die Steuerung hat angehalten (ALARM:%1). Bringen Sie die Maschine in einen sicheren Zustand, entsperren Sie dann ($X) oder setzen Sie die Steuerung zurück; die Bedeutung dieses Alarms steht in der Dokumentation der Steuerung.</translation>
    </message>
    <message>
        <source>The controller could not read a word of the line (a letter and a number each). Check the line.</source>
        <translation>Die Steuerung konnte ein Wort der Zeile nicht lesen (jeweils ein Buchstabe und eine Zahl). Prüfen Sie die Zeile.</translation>
    </message>
    <message>
        <source>The controller does not know this $ command.</source>
        <translation>Die Steuerung kennt diesen $-Befehl nicht.</translation>
    </message>
    <message>
        <source>The controller takes this $ command only while idle: wait for the machine to stop, then try again.</source>
        <translation>Die Steuerung nimmt diesen $-Befehl nur im Stillstand an: Warten Sie, bis die Maschine steht, und versuchen Sie es dann erneut.</translation>
    </message>
    <message>
        <source>G-code locked out during alarm or jog state: the controller is halted. Find out why it halted, unlock ($X), then try again.</source>
        <translation>G-Code ist im Alarm- oder Tippbetrieb gesperrt: Die Steuerung ist angehalten. Ermitteln Sie die Ursache, entsperren Sie ($X) und versuchen Sie es dann erneut.</translation>
    </message>
    <message>
        <source>The line is too long for the controller; it was not carried out.</source>
        <translation>Die Zeile ist für die Steuerung zu lang; sie wurde nicht ausgeführt.</translation>
    </message>
    <message>
        <source>The safety door is open. Close it and go on.</source>
        <translation>Die Schutztür ist offen. Schließen Sie sie und arbeiten Sie weiter.</translation>
    </message>
    <message>
        <source>The jog would go beyond the machine&apos;s travel; the machine did not move.</source>
        <translation>Die Tippbewegung würde den Verfahrweg der Maschine überschreiten; die Maschine hat sich nicht bewegt.</translation>
    </message>
    <message>
        <source>The controller was reset; the line was not carried out.</source>
        <translation>Die Steuerung wurde zurückgesetzt; die Zeile wurde nicht ausgeführt.</translation>
    </message>
    <message>
        <source>The controller does not support a command in the line (or the command is not valid there).</source>
        <translation>Die Steuerung unterstützt einen Befehl in der Zeile nicht (oder der Befehl ist dort nicht zulässig).</translation>
    </message>
    <message>
        <source>The line holds words that cannot go together. Check the line.</source>
        <translation>Die Zeile enthält Wörter, die nicht zusammen stehen dürfen. Prüfen Sie die Zeile.</translation>
    </message>
    <message>
        <source>No feed rate is set for the move: give one with F.</source>
        <translation>Für die Bewegung ist kein Vorschub gesetzt: Geben Sie einen mit F an.</translation>
    </message>
    <message>
        <source>A command in the line lacks a value or needs a whole number. Check the line.</source>
        <translation>Einem Befehl in der Zeile fehlt ein Wert, oder er erfordert eine ganze Zahl. Prüfen Sie die Zeile.</translation>
    </message>
    <message>
        <source>The move has no valid target. Check its axis words.</source>
        <translation>Die Bewegung hat kein gültiges Ziel. Prüfen Sie ihre Achswörter.</translation>
    </message>
    <message>
        <source>G43.1 was given for an axis that is not the controller&apos;s tool length axis (Z).</source>
        <translation>G43.1 wurde für eine Achse angegeben, die nicht die Werkzeuglängenachse der Steuerung (Z) ist.</translation>
    </message>
    <message>
        <source>No such tool in the controller: the number is beyond its tool table, or the tool is not in it. Check the table&apos;s size ($I) and the tool&apos;s number.</source>
        <translation>Dieses Werkzeug gibt es in der Steuerung nicht: Die Nummer liegt außerhalb ihrer Werkzeugtabelle, oder das Werkzeug ist nicht darin eingetragen. Prüfen Sie die Größe der Tabelle ($I) und die Werkzeugnummer.</translation>
    </message>
    <message>
        <source>A value in the line is out of the range the controller takes.</source>
        <translation>Ein Wert in der Zeile liegt außerhalb des Bereichs, den die Steuerung annimmt.</translation>
    </message>
    <message>
        <source>A tool change is waiting to be finished: finish it (cycle start) before sending more.</source>
        <translation>Ein Werkzeugwechsel wartet auf seinen Abschluss: Schließen Sie ihn ab (Zyklusstart), bevor Sie weitere Befehle senden.</translation>
    </message>
    <message>
        <source>A limit switch is pressed: only homing is allowed. Move off the switch or home ($H).</source>
        <translation>Ein Endschalter ist betätigt: Nur eine Referenzfahrt ist erlaubt. Fahren Sie vom Schalter frei oder führen Sie eine Referenzfahrt durch ($H).</translation>
    </message>
    <message>
        <source>The machine must be homed first: home it ($H).</source>
        <translation>Die Maschine braucht zuerst eine Referenzfahrt: Führen Sie sie durch ($H).</translation>
    </message>
    <message>
        <source>The controller does not know which tool is in the spindle: tell it with M61 Q&lt;n&gt;.</source>
        <translation>Die Steuerung weiß nicht, welches Werkzeug in der Spindel ist: Teilen Sie es ihr mit M61 Q&lt;n&gt; mit.</translation>
    </message>
    <message>
        <source>The controller&apos;s power-on self test failed: switch it off and on.</source>
        <translation>Der Selbsttest der Steuerung beim Einschalten ist fehlgeschlagen: Schalten Sie sie aus und wieder ein.</translation>
    </message>
    <message>
        <source>The emergency stop is engaged. Release it and reset the controller.</source>
        <translation>Der Not-Halt ist ausgelöst. Entriegeln Sie ihn und setzen Sie die Steuerung zurück.</translation>
    </message>
    <message>
        <source>Not allowed while a critical event is active (an emergency stop, a hard limit or a motor fault). Clear it and reset the controller.</source>
        <translation>Nicht erlaubt, solange ein kritisches Ereignis aktiv ist (Not-Halt, ausgelöster Hardware-Endschalter oder Motorfehler). Beheben Sie es und setzen Sie die Steuerung zurück.</translation>
    </message>
    <message>
        <source>There is already a tool in the spindle: remove it first.</source>
        <translation>Es ist bereits ein Werkzeug in der Spindel: Entnehmen Sie es zuerst.</translation>
    </message>
    <message>
        <source>There is no tool in the spindle: put one in (or tell the controller with M61 Q&lt;n&gt;).</source>
        <translation>Es ist kein Werkzeug in der Spindel: Setzen Sie eines ein (oder teilen Sie es der Steuerung mit M61 Q&lt;n&gt; mit).</translation>
    </message>
    <message>
        <source>The controller refused the line (error:%1).</source>
        <translation>Die Steuerung hat die Zeile abgelehnt (error:%1).</translation>
    </message>
</context>
<context>
    <name>Toffee::GrblHalController</name>
    <message>
        <source>grblHAL answered $G without its modal state ([GC:…]); is this grblHAL?</source>
        <translation>grblHAL hat auf $G ohne seinen modalen Zustand ([GC:…]) geantwortet; ist das grblHAL?</translation>
    </message>
    <message>
        <source>The machine answered but sent no status report when asked; is it grblHAL? If it is a Carvera, choose the Carvera (--controller carvera).</source>
        <translation>Die Maschine hat geantwortet, auf Anfrage aber keinen Statusbericht gesendet; ist es grblHAL? Ist es eine Carvera, wählen Sie die Carvera (--controller carvera).</translation>
    </message>
    <message>
        <source>This controller answered $I as Grbl does but did not say it is grblHAL ([FIRMWARE:grblHAL]); it may be classic Grbl, which keeps no tool table. Toffee manages grblHAL and the Carvera.</source>
        <translation>Diese Steuerung hat auf $I wie Grbl geantwortet, sich aber nicht als grblHAL ausgewiesen ([FIRMWARE:grblHAL]); vielleicht ist es das klassische Grbl, das keine Werkzeugtabelle führt. Toffee verwaltet grblHAL und die Carvera.</translation>
    </message>
    <message>
        <source>This machine did not answer $I as grblHAL does. If it is a Carvera, connect with the Carvera chosen (--controller carvera).</source>
        <translation>Diese Maschine hat auf $I nicht wie grblHAL geantwortet. Ist es eine Carvera, verbinden Sie sich mit ausgewählter Carvera (--controller carvera).</translation>
    </message>
    <message>
        <source>grblHAL sent no status report within 2 s.</source>
        <translation>grblHAL hat innerhalb von 2 s keinen Statusbericht gesendet.</translation>
    </message>
    <message>
        <source>grblHAL says no tool is in the spindle (T0), so there is nothing to %1. Say which tool is in (Select Tool, M61 Q&lt;n&gt;) first.</source>
        <translation>grblHAL meldet kein Werkzeug in der Spindel (T0), daher lässt sich nichts %1. Geben Sie zuerst an, welches Werkzeug eingesetzt ist (Werkzeug auswählen, M61 Q&lt;n&gt;).</translation>
    </message>
    <message>
        <source>Toffee does not know where this machine&apos;s tool setter is. Set it first (Machine ▸ Tool Setter…, or toffee-cli --setter X,Y,ZMIN in machine coordinates).</source>
        <translation>Toffee weiß nicht, wo der Werkzeugtaster dieser Maschine ist. Legen Sie ihn zuerst fest (Maschine ▸ Werkzeugtaster …, oder toffee-cli --setter X,Y,ZMIN in Maschinenkoordinaten).</translation>
    </message>
    <message>
        <source>The probe did not report a touch. Nothing was measured.</source>
        <translation>Der Taster hat keine Berührung gemeldet. Es wurde nichts gemessen.</translation>
    </message>
    <message>
        <source>the offset in force reads %1 mm</source>
        <translation>die wirksame Korrektur lautet %1 mm</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <source>T%1&apos;s entry reads %2 mm</source>
        <translation>der Eintrag von T%1 lautet %2 mm</translation>
    </message>
    <message>
        <source>grblHAL was given T%1&apos;s TLO %2 mm, but read back %3. Nothing was recorded; check the controller&apos;s offsets ($#) before you cut.</source>
        <translation>grblHAL wurde die TLO %2 mm von T%1 übergeben, zurückgelesen wurde aber: %3. Es wurde nichts aufgezeichnet; prüfen Sie die Korrekturen der Steuerung ($#), bevor Sie zerspanen.</translation>
    </message>
    <message>
        <source>T%1 is beyond grblHAL&apos;s table of %2 tools: its TLO is in force (G43.1) but not stored in the controller.</source>
        <translation>T%1 liegt außerhalb der Tabelle von grblHAL mit %2 Werkzeugen: Seine TLO ist wirksam (G43.1), aber nicht in der Steuerung gespeichert.</translation>
    </message>
    <message>
        <source>This grblHAL keeps no tool table: the TLO is in force (G43.1) until a reset.</source>
        <translation>Dieses grblHAL führt keine Werkzeugtabelle: Die TLO ist bis zu einem Reset wirksam (G43.1).</translation>
    </message>
    <message>
        <source>measure</source>
        <translation>vermessen</translation>
    </message>
    <message>
        <source>break-test</source>
        <translation>auf Bruch prüfen</translation>
    </message>
    <message>
        <source>The TLO</source>
        <translation>Die TLO</translation>
    </message>
    <message>
        <source>set a TLO for</source>
        <translation>mit einer TLO versehen</translation>
    </message>
    <message>
        <source>The height above Z0</source>
        <translation>Die Höhe über Z0</translation>
    </message>
    <message>
        <source>grblHAL sent no status report, so the tool&apos;s height is not known.</source>
        <translation>grblHAL hat keinen Statusbericht gesendet, daher ist die Höhe des Werkzeugs nicht bekannt.</translation>
    </message>
    <message>
        <source>grblHAL was told T%1 is in the spindle but reports T%2.</source>
        <translation>grblHAL wurde mitgeteilt, dass T%1 in der Spindel ist, meldet aber T%2.</translation>
    </message>
    <message>
        <source>grblHAL changes to a tool, not to an empty spindle: use Select Tool with T0.</source>
        <translation>grblHAL wechselt zu einem Werkzeug, nicht zu einer leeren Spindel: Verwenden Sie „Werkzeug auswählen“ mit T0.</translation>
    </message>
    <message>
        <source>A TLO is restored for a tool, not for an empty spindle.</source>
        <translation>Eine TLO wird für ein Werkzeug wiederhergestellt, nicht für eine leere Spindel.</translation>
    </message>
    <message>
        <source>%1 (the TLO that puts the tip %2 mm above Z0, from where it is)</source>
        <translation>%1 (die TLO, die die Spitze von ihrer jetzigen Position aus %2 mm über Z0 setzt)</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO</source>
        <translation>Die TLO von T%1</translation>
    </message>
    <message>
        <source>grblHAL&apos;s table holds T1 to T%1; %2 cannot be written. Nothing was written: renumber them or leave them out.</source>
        <translation>Die Tabelle von grblHAL umfasst T1 bis T%1; nicht schreibbar sind: %2. Es wurde nichts geschrieben: Nummerieren Sie sie um oder lassen Sie sie weg.</translation>
    </message>
    <message>
        <source>T%1 reads %2 mm, not %3 mm</source>
        <translation>T%1 lautet %2 mm, nicht %3 mm</translation>
    </message>
    <message>
        <source>grblHAL&apos;s table does not read back as written: %1.</source>
        <translation>Die Tabelle von grblHAL liest sich nicht so zurück, wie sie geschrieben wurde: %1.</translation>
    </message>
    <message>
        <source>grblHAL&apos;s offsets ($#) could not be read whole: lines were malformed or repeated (%1). Nothing was changed; check the connection and try again.</source>
        <translation>Die Korrekturen von grblHAL ($#) ließen sich nicht vollständig lesen: Zeilen waren fehlerhaft oder doppelt (%1). Nichts wurde geändert; prüfen Sie die Verbindung und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>T%1 is put in by hand (grblHAL&apos;s manual tool change)</source>
        <translation>T%1 wird von Hand eingesetzt (manueller Werkzeugwechsel von grblHAL)</translation>
    </message>
    <message>
        <source>grblHAL stopped reporting its state during the change to T%1.</source>
        <translation>grblHAL hat während des Wechsels zu T%1 aufgehört, seinen Zustand zu melden.</translation>
    </message>
    <message>
        <source>grblHAL went into alarm during the change to T%1: nothing was measured.</source>
        <translation>grblHAL ist während des Wechsels zu T%1 in den Alarm gegangen: Nichts wurde gemessen.</translation>
    </message>
    <message>
        <source>grblHAL was reset to end it: its tool is still T%1, with no offset in force. Check what is in the spindle, then select it and restore or probe its TLO before cutting.</source>
        <translation>grblHAL wurde zurückgesetzt, um ihn zu beenden: Sein Werkzeug ist noch T%1, ohne wirksame Korrektur. Prüfen Sie, was in der Spindel steckt, wählen Sie es dann aus und stellen Sie seine Längenkorrektur wieder her oder messen Sie sie, bevor Sie schneiden.</translation>
    </message>
    <message>
        <source>grblHAL is in inches (G20), where its G10 and G38.2 take inches. Toffee %1 in millimetres: send G21, then try again. Nothing was sent.</source>
        <translation>grblHAL ist auf Zoll eingestellt (G20), in dem seine G10 und G38.2 Zoll nehmen. Toffee %1 in Millimetern: Senden Sie G21 und versuchen Sie es dann erneut. Nichts wurde gesendet.</translation>
    </message>
    <message>
        <source>grblHAL reports in inches ($13=1); Toffee reads millimetres. Set $13=0 (reports in millimetres), then connect again.</source>
        <translation>grblHAL meldet in Zoll ($13=1); Toffee liest Millimeter. Setzen Sie $13=0 (Meldungen in Millimetern) und verbinden Sie sich dann erneut.</translation>
    </message>
    <message>
        <source>probes</source>
        <translation>misst</translation>
    </message>
    <message>
        <source>writes TLOs</source>
        <translation>schreibt Längenkorrekturen</translation>
    </message>
    <message>
        <source>writes its table</source>
        <translation>schreibt seine Tabelle</translation>
    </message>
    <message>
        <source>grblHAL reported the contact at machine Z %1 mm, outside the search from %2 to %3 mm. Nothing was written or recorded; check the tool setter&apos;s settings and the machine.</source>
        <translation>grblHAL hat die Berührung bei Maschinen-Z %1 mm gemeldet, außerhalb der Suche von %2 bis %3 mm. Nichts wurde geschrieben oder aufgezeichnet; prüfen Sie die Einstellungen des Werkzeugtasters und die Maschine.</translation>
    </message>
    <message>
        <source>Nothing was written to grblHAL or recorded.</source>
        <translation>Nichts wurde in grblHAL geschrieben oder aufgezeichnet.</translation>
    </message>
    <message>
        <source>A jog moves at most %1 mm along each axis, at 1 to %2 mm/min. Nothing was sent.</source>
        <translation>Ein Tippbetrieb bewegt höchstens %1 mm je Achse, mit 1 bis %2 mm/min. Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>A jog of 0 mm moves nothing. Nothing was sent.</source>
        <translation>Ein Tippbetrieb um 0 mm bewegt nichts. Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>grblHAL stopped reporting its state while it jogged.</source>
        <translation>grblHAL hat während des Tippbetriebs aufgehört, seinen Zustand zu melden.</translation>
    </message>
    <message>
        <source>grblHAL went into alarm while it jogged: check the machine, then Unlock.</source>
        <translation>grblHAL ging während des Tippbetriebs in Alarm: Prüfen Sie die Maschine, dann Entsperren.</translation>
    </message>
    <message>
        <source>The jog was stopped where the machine stands; it is ready (no alarm).</source>
        <translation>Das Verfahren wurde dort angehalten, wo die Maschine steht; sie ist bereit (kein Alarm).</translation>
    </message>
    <message>
        <source>T%1 cannot be probed so: %2 Nothing was sent.</source>
        <translation>T%1 kann so nicht angetastet werden: %2 Es wurde nichts gesendet.</translation>
    </message>
</context>
<context>
    <name>Toffee::GuideDialog</name>
    <message>
        <source>Toffee&apos;s User&apos;s Guide</source>
        <translation>Toffee-Benutzerhandbuch</translation>
    </message>
    <message>
        <source>%1 is not installed with Toffee: it is in the docs folder of Toffee&apos;s source.</source>
        <translation>%1 wird mit Toffee nicht installiert: Sie finden es im Ordner docs der Quellen von Toffee.</translation>
    </message>
    <message>
        <source>The user&apos;s guide is missing</source>
        <translation>Das Benutzerhandbuch fehlt</translation>
    </message>
    <message>
        <source>The user&apos;s guide is not where Toffee installs it (%1). Reinstall Toffee&apos;s package, or read docs/GUIDE.md in its source.</source>
        <translation>Das Benutzerhandbuch ist nicht dort, wo Toffee es installiert (%1). Installieren Sie das Paket von Toffee neu oder lesen Sie docs/GUIDE.md in den Quellen.</translation>
    </message>
</context>
<context>
    <name>Toffee::HistoryDock</name>
    <message>
        <source>probe</source>
        <translation>Messung</translation>
    </message>
    <message>
        <source>break test</source>
        <translation>Bruchtest</translation>
    </message>
    <message>
        <source>set by hand</source>
        <translation>von Hand gesetzt</translation>
    </message>
    <message>
        <source>restored</source>
        <translation>wiederhergestellt</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>Als CSV exportieren…</translation>
    </message>
    <message>
        <source>Copy Chart</source>
        <translation>Diagramm kopieren</translation>
    </message>
    <message>
        <source>TLO over time</source>
        <translation>TLO über die Zeit</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>Messungen</translation>
    </message>
    <message>
        <source>Select one tool to see its history.</source>
        <translation>Wählen Sie ein Werkzeug, um seinen Verlauf zu sehen.</translation>
    </message>
    <message>
        <source>T%1: the history library is not open.</source>
        <translation>T%1: Die Verlaufsbibliothek ist nicht geöffnet.</translation>
    </message>
    <message>
        <source>T%1 on %2: 1 measurement</source>
        <translation>T%1 auf %2: 1 Messung</translation>
    </message>
    <message>
        <source>T%1 on %2: %3 measurements</source>
        <translation>T%1 auf %2: %3 Messungen</translation>
    </message>
    <message>
        <source>Probes</source>
        <translation>Messungen</translation>
    </message>
    <message>
        <source>Break test passed</source>
        <translation>Bruchtest bestanden</translation>
    </message>
    <message>
        <source>Break test failed</source>
        <translation>Bruchtest nicht bestanden</translation>
    </message>
    <message>
        <source>Set by hand</source>
        <translation>Von Hand gesetzt</translation>
    </message>
    <message>
        <source>Wear trend</source>
        <translation>Verschleißtrend</translation>
    </message>
    <message>
        <source>± %1 mm</source>
        <translation>± %1 mm</translation>
    </message>
    <message>
        <source>No measurements of T%1 yet</source>
        <translation>Noch keine Messungen von T%1</translation>
    </message>
    <message>
        <source>TLO (mm)</source>
        <translation>TLO (mm)</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <source>TLO</source>
        <translation>TLO</translation>
    </message>
    <message>
        <source>Reference Z</source>
        <translation>Referenz-Z</translation>
    </message>
    <message>
        <source>Current Z</source>
        <translation>Aktuelles Z</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <source>Old TLO</source>
        <translation>Alte TLO</translation>
    </message>
    <message>
        <source>New TLO</source>
        <translation>Neue TLO</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>BROKEN?</source>
        <translation>GEBROCHEN?</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>bestanden</translation>
    </message>
    <message>
        <source>The chart cannot be drawn: Toffee&apos;s chart module %1 is missing. Reinstall Toffee; the measurements are in the table below.</source>
        <translation>Das Diagramm kann nicht gezeichnet werden: Toffees Diagrammmodul %1 fehlt. Installieren Sie Toffee neu; die Messungen stehen in der Tabelle darunter.</translation>
    </message>
    <message>
        <source>The chart cannot be drawn: Toffee&apos;s chart module %1 cannot be loaded (%2). Reinstall Toffee; the measurements are in the table below.</source>
        <translation>Das Diagramm kann nicht gezeichnet werden: Toffees Diagrammmodul %1 kann nicht geladen werden (%2). Installieren Sie Toffee neu; die Messungen stehen in der Tabelle darunter.</translation>
    </message>
    <message>
        <source>read in</source>
        <translation>eingelesen</translation>
    </message>
    <message>
        <source>new cutter (old one ended)</source>
        <translation>neuer Fräser (alter beendet)</translation>
    </message>
    <message>
        <source>Old cutter</source>
        <translation>Alter Fräser</translation>
    </message>
    <message>
        <source>Spread</source>
        <translation>Streuung</translation>
    </message>
    <message>
        <source>%1 touches, at machine Z %2 mm: the TLO is the highest&apos;s (the longest edge)</source>
        <translation>%1 Antastungen bei Maschinen-Z %2 mm: Die TLO ist die der höchsten (der längsten Schneide)</translation>
    </message>
    <message>
        <source>Each edge</source>
        <translation>Jede Schneide</translation>
    </message>
</context>
<context>
    <name>Toffee::HistoryRecorder</name>
    <message>
        <source>The library (%1) cannot be reached: its server stopped answering. Toffee keeps what you record and writes it when the server is back.</source>
        <translation>Die Bibliothek (%1) ist nicht erreichbar: Der Server antwortet nicht mehr. Toffee behält, was Sie aufzeichnen, und schreibt es, sobald der Server wieder da ist.</translation>
    </message>
</context>
<context>
    <name>Toffee::HistorySettingsDialog</name>
    <message>
        <source>History Library</source>
        <translation>Verlaufsbibliothek</translation>
    </message>
    <message>
        <source>Machine name</source>
        <translation>Maschinenname</translation>
    </message>
    <message>
        <source> days</source>
        <translation> Tage</translation>
    </message>
    <message>
        <source>Stale after</source>
        <translation>Veraltet nach</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>Durchsuchen…</translation>
    </message>
    <message>
        <source>This machine&apos;s name:</source>
        <translation>Name dieser Maschine:</translation>
    </message>
    <message>
        <source>A measurement is stale after:</source>
        <translation>Eine Messung ist veraltet nach:</translation>
    </message>
    <message>
        <source>SQLite libraries (*.sqlite *.db);;All files (*)</source>
        <translation>SQLite-Bibliotheken (*.sqlite *.db);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>This library cannot be used: %1</source>
        <translation>Diese Bibliothek lässt sich nicht verwenden: %1</translation>
    </message>
    <message>
        <source>Library file or URL</source>
        <translation>Bibliotheksdatei oder URL</translation>
    </message>
    <message>
        <source>A file, or postgresql://user@server/database</source>
        <translation>Eine Datei oder postgresql://user@server/database</translation>
    </message>
    <message>
        <source>An SQLite file for this computer, or a shared PostgreSQL database as postgresql://user@host:port/dbname?sslmode=require. The password goes in the PostgreSQL password file (~/.pgpass), never in the URL.</source>
        <translation>Eine SQLite-Datei für diesen Computer oder eine gemeinsame PostgreSQL-Datenbank als postgresql://user@host:port/dbname?sslmode=require. Das Passwort gehört in die PostgreSQL-Passwortdatei (~/.pgpass), nie in die URL.</translation>
    </message>
    <message>
        <source>Choose a library file</source>
        <translation>Bibliotheksdatei wählen</translation>
    </message>
    <message>
        <source>Library file or URL:</source>
        <translation>Bibliotheksdatei oder URL:</translation>
    </message>
    <message>
        <source>This station&apos;s name</source>
        <translation>Name dieses Arbeitsplatzes</translation>
    </message>
    <message>
        <source>Who this computer&apos;s changes are from in a shared library, as the other stations see it; empty: the computer&apos;s name.</source>
        <translation>Von wem die Änderungen dieses Computers in einer gemeinsamen Bibliothek stammen, wie die anderen Arbeitsplätze es sehen; leer: der Name des Computers.</translation>
    </message>
    <message>
        <source>This station&apos;s name:</source>
        <translation>Name dieses Arbeitsplatzes:</translation>
    </message>
    <message>
        <source>Its kind: Carvera, grblHAL or Emulator</source>
        <translation>Ihre Art: Carvera, grblHAL oder Emulator</translation>
    </message>
    <message>
        <source>The name this machine&apos;s history, reference and tool setter are kept under. Left empty, the machine is called after its kind. A name stands for one machine: another machine under it is asked about.</source>
        <translation>Der Name, unter dem Verlauf, Referenz und Werkzeugsensor dieser Maschine geführt werden. Leer gelassen, heißt die Maschine nach ihrer Art. Ein Name steht für eine Maschine: Bei einer anderen Maschine unter diesem Namen wird nachgefragt.</translation>
    </message>
</context>
<context>
    <name>Toffee::HsmReader</name>
    <message>
        <source>there is no XML element in it</source>
        <translation>es enthält kein XML-Element</translation>
    </message>
    <message>
        <source>column %1: this is not an HSM tool library: its root element is &lt;%2&gt; in namespace &quot;%3&quot;, where a library has &lt;tool-library&gt; in &quot;%4&quot;.</source>
        <translation>Spalte %1: das ist keine HSM-Werkzeugbibliothek: ihr Wurzelelement ist &lt;%2&gt; im Namensraum „%3“, eine Bibliothek hat &lt;tool-library&gt; in „%4“.</translation>
    </message>
    <message>
        <source>column %1: this is not well-formed XML (%2).</source>
        <translation>Spalte %1: das ist kein wohlgeformtes XML (%2).</translation>
    </message>
    <message>
        <source>tool %1</source>
        <translation>Werkzeug %1</translation>
    </message>
    <message>
        <source>its unit is &quot;%1&quot;; Toffee reads millimeters or inches.</source>
        <translation>seine Einheit ist „%1“; Toffee liest millimeters oder inches.</translation>
    </message>
    <message>
        <source>it has no &lt;nc number=…&gt;: Toffee needs the T number the post writes.</source>
        <translation>es hat kein &lt;nc number=…&gt;: Toffee braucht die T-Nummer, die der Postprozessor schreibt.</translation>
    </message>
    <message>
        <source>its nc number is &quot;%1&quot;, not a tool number.</source>
        <translation>seine nc-Nummer ist „%1“, keine Werkzeugnummer.</translation>
    </message>
    <message>
        <source>it has a second &lt;%1&gt; (the first is on line %2); a tool has one, and Toffee will not guess which one is meant.</source>
        <translation>es hat ein zweites &lt;%1&gt; (das erste steht in Zeile %2); ein Werkzeug hat nur eines, und Toffee rät nicht, welches gemeint ist.</translation>
    </message>
    <message>
        <source>its nc length-offset is &quot;%1&quot;, not a whole number.</source>
        <translation>sein nc-length-offset ist „%1“, keine ganze Zahl.</translation>
    </message>
    <message>
        <source>its body %1 is &quot;%2&quot;, not a number.</source>
        <translation>sein body-Attribut %1 ist „%2“, keine Zahl.</translation>
    </message>
</context>
<context>
    <name>Toffee::ImportPreview</name>
    <message>
        <source>flute length</source>
        <translation>Schneidenlänge</translation>
    </message>
    <message>
        <source>below the holder</source>
        <translation>unter dem Halter</translation>
    </message>
    <message>
        <source>overall length</source>
        <translation>Gesamtlänge</translation>
    </message>
    <message>
        <source>description “%1” → “%2”</source>
        <translation>Beschreibung „%1“ → „%2“</translation>
    </message>
    <message>
        <source>radius %1 → %2 %3</source>
        <translation>Radius %1 → %2 %3</translation>
    </message>
    <message>
        <source>pocket %1; no tool length yet (0 in the table): measure it before use</source>
        <translation>Platz %1; noch keine Werkzeuglänge (0 in der Tabelle): vor dem Einsatz messen</translation>
    </message>
    <message>
        <source>the library gives length offset H%1; Toffee always uses H = T (H%2), so it is not imported</source>
        <translation>die Bibliothek gibt die Längenkorrektur H%1 an; Toffee verwendet immer H = T (H%2), daher wird sie nicht importiert</translation>
    </message>
    <message>
        <source>CAM lengths added to the notes (%1)</source>
        <translation>CAM-Längen in die Notizen aufgenommen (%1)</translation>
    </message>
    <message>
        <source>CAM lengths in the notes: %1 → %2</source>
        <translation>CAM-Längen in den Notizen: %1 → %2</translation>
    </message>
    <message>
        <source>T%1 is in the library twice.</source>
        <translation>T%1 steht zweimal in der Bibliothek.</translation>
    </message>
    <message>
        <source>the CAM lengths line in the notes</source>
        <translation>die Zeile mit den CAM-Längen in den Notizen</translation>
    </message>
    <message>
        <source>%1 new, %2 changed, %3 unchanged</source>
        <translation>%1 neu, %2 geändert, %3 unverändert</translation>
    </message>
    <message>
        <source>type “%1” → “%2”</source>
        <translation>Typ „%1“ → „%2“</translation>
    </message>
    <message>
        <source>diameter %1 → %2 %3</source>
        <translation>Durchmesser %1 → %2 %3</translation>
    </message>
    <message>
        <source>overall length %1 → %2 %3</source>
        <translation>Gesamtlänge %1 → %2 %3</translation>
    </message>
    <message>
        <source>the library gives no unit: its lengths are read in %1, as you said</source>
        <translation>die Bibliothek gibt keine Einheit an: Die Längen werden wie angegeben in %1 gelesen</translation>
    </message>
    <message>
        <source>inches</source>
        <translation>Zoll</translation>
    </message>
    <message>
        <source>millimetres</source>
        <translation>Millimetern</translation>
    </message>
    <message>
        <source>%1; a new cutter in %2 (measure before use)</source>
        <translation>%1; ein neuer Fräser bei %2 (vor Gebrauch vermessen)</translation>
    </message>
    <message>
        <source>Tools in this library without &quot;unit&quot; (millimeters or inches): %1. Their diameters and lengths cannot be read. Fusion writes one on every tool: export the library from Fusion again, or add &quot;unit&quot;: &quot;millimeters&quot; (or &quot;inches&quot;) to each, or say which unit they are in (the window asks; toffee-cli import --cam-units mm|in).</source>
        <translation>Werkzeuge dieser Bibliothek ohne „unit“ (millimeters oder inches): %1. Ihre Durchmesser und Längen lassen sich nicht lesen. Fusion schreibt sie an jedes Werkzeug: Exportieren Sie die Bibliothek erneut aus Fusion, ergänzen Sie bei jedem &quot;unit&quot;: &quot;millimeters&quot; (oder &quot;inches&quot;), oder geben Sie an, in welcher Einheit sie sind (das Fenster fragt; toffee-cli import --cam-units mm|in).</translation>
    </message>
    <message>
        <source>a new cutter (%1): the old cutter&apos;s TLO %2 %3, its length, wear and break mark end; measure it before it cuts</source>
        <translation>ein neuer Fräser (%1): die TLO %2 %3 des alten Fräsers, seine Länge, sein Verschleiß und seine Bruchmarke enden; vor dem Schneiden vermessen</translation>
    </message>
    <message>
        <source>a new cutter (%1): the old cutter&apos;s length, wear and break mark end; measure it before it cuts</source>
        <translation>ein neuer Fräser (%1): Länge, Verschleiß und Bruchmarke des alten Fräsers enden; vor dem Schneiden vermessen</translation>
    </message>
</context>
<context>
    <name>Toffee::ImportPreviewDialog</name>
    <message>
        <source>New</source>
        <translation>Neu</translation>
    </message>
    <message>
        <source>Changed</source>
        <translation>Geändert</translation>
    </message>
    <message>
        <source>Unchanged</source>
        <translation>Unverändert</translation>
    </message>
    <message>
        <source>&amp;Import</source>
        <translation>&amp;Importieren</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Import tools</source>
        <translation>Werkzeuge importieren</translation>
    </message>
    <message>
        <source>Import Tools from %1</source>
        <translation>Werkzeuge aus %1 importieren</translation>
    </message>
    <message>
        <source>What the import does</source>
        <translation>Was der Import ändert</translation>
    </message>
    <message>
        <source>%1 (%2): %3.</source>
        <translation>%1 (%2): %3.</translation>
    </message>
    <message>
        <source>Only descriptions, radii and the CAM&apos;s line in the notes change; measured TLOs, wear, pockets and your notes stay as they are.</source>
        <translation>Nur Beschreibungen, Radien und die CAM-Zeile in den Notizen ändern sich; gemessene Längenkorrekturen, Verschleiß, Plätze und Ihre Notizen bleiben, wie sie sind.</translation>
    </message>
    <message>
        <source>The table already has these tools as the library describes them.</source>
        <translation>Die Tabelle hat diese Werkzeuge schon so, wie die Bibliothek sie beschreibt.</translation>
    </message>
    <message>
        <source>Tools in the library</source>
        <translation>Werkzeuge in der Bibliothek</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>Import</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Changes</source>
        <translation>Änderungen</translation>
    </message>
    <message>
        <source>Changes and notes of the selected tool</source>
        <translation>Änderungen und Hinweise zum ausgewählten Werkzeug</translation>
    </message>
    <message>
        <source>T%1 (%2): %3</source>
        <translation>T%1 (%2): %3</translation>
    </message>
    <message>
        <source>The table already has this tool as the library describes it.</source>
        <translation>Die Tabelle hat dieses Werkzeug schon so, wie die Bibliothek es beschreibt.</translation>
    </message>
    <message>
        <source>Import the tools</source>
        <translation>Die Werkzeuge importieren</translation>
    </message>
    <message>
        <source>Cancel the import</source>
        <translation>Den Import abbrechen</translation>
    </message>
    <message>
        <source>Import or cancel</source>
        <translation>Importieren oder abbrechen</translation>
    </message>
    <message>
        <source>Only descriptions, radii and the CAM&apos;s line in the notes change, except where the library describes another cutter: that tool&apos;s TLO, length, wear and break mark end (the history keeps the TLO) and it is measured before it cuts. Pockets and your notes stay as they are.</source>
        <translation>Nur Beschreibungen, Radien und die CAM-Zeile in den Notizen ändern sich, außer wo die Bibliothek einen anderen Fräser beschreibt: TLO, Länge, Verschleiß und Bruchmarke dieses Werkzeugs enden (der Verlauf behält die TLO), und es wird vor dem Schneiden vermessen. Plätze und Ihre Notizen bleiben, wie sie sind.</translation>
    </message>
</context>
<context>
    <name>Toffee::JobCheckDialog</name>
    <message>
        <source>Z &amp;floor:</source>
        <translation>Z-&amp;Untergrenze:</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Check &amp;Again</source>
        <translation>&amp;Erneut prüfen</translation>
    </message>
    <message>
        <source>&amp;Prepare…</source>
        <translation>&amp;Vorbereiten …</translation>
    </message>
    <message>
        <source>Tools in order of use</source>
        <translation>Werkzeuge in Reihenfolge der Verwendung</translation>
    </message>
    <message>
        <source>Findings</source>
        <translation>Befunde</translation>
    </message>
    <message>
        <source>Check Job</source>
        <translation>Job prüfen</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>Steuerung</translation>
    </message>
    <message>
        <source>Lowest work Z a feed move may reach</source>
        <translation>Tiefstes Werkstück-Z, das eine Vorschubbewegung erreichen darf</translation>
    </message>
    <message>
        <source>The tools the Carvera&apos;s rack holds</source>
        <translation>Die Werkzeuge im Magazin der Carvera</translation>
    </message>
    <message>
        <source>The tools the rack holds: 1-6 on a Carvera C1, none on a machine without one, or a list such as 1-4,8. Every other tool is a manual change.</source>
        <translation>Die Werkzeuge im Magazin: 1-6 bei einer Carvera C1, none bei einer Maschine ohne Magazin oder eine Liste wie 1-4,8. Jedes andere Werkzeug ist ein manueller Wechsel.</translation>
    </message>
    <message>
        <source>How far the check is</source>
        <translation>Fortschritt der Prüfung</translation>
    </message>
    <message>
        <source>The program around the finding</source>
        <translation>Das Programm rund um den Befund</translation>
    </message>
    <message>
        <source>Double-click a finding to see the program around its line.</source>
        <translation>Doppelklicken Sie auf einen Befund, um das Programm rund um seine Zeile zu sehen.</translation>
    </message>
    <message>
        <source>Controller:</source>
        <translation>Steuerung:</translation>
    </message>
    <message>
        <source>&amp;Tools, in order of use</source>
        <translation>&amp;Werkzeuge in Reihenfolge der Verwendung</translation>
    </message>
    <message>
        <source>F&amp;indings, by line</source>
        <translation>&amp;Befunde nach Zeile</translation>
    </message>
    <message>
        <source>Program: %1</source>
        <translation>Programm: %1</translation>
    </message>
    <message>
        <source>Checking…</source>
        <translation>Wird geprüft …</translation>
    </message>
    <message>
        <source>The program could not be checked: %1</source>
        <translation>Das Programm ließ sich nicht prüfen: %1</translation>
    </message>
    <message>
        <source>%1: %2 lines as %3; tools: %4, cutting %5, rapids %6 mm.</source>
        <translation>%1: %2 Zeilen als %3; Werkzeuge: %4, Schnittzeit %5, Eilgang %6 mm.</translation>
    </message>
    <message>
        <source>Cancelled after %1 lines: what was found so far.</source>
        <translation>Nach %1 Zeilen abgebrochen: was bis dahin gefunden wurde.</translation>
    </message>
    <message>
        <source>The check found errors: fix them before preparing the program.</source>
        <translation>Die Prüfung hat Fehler gefunden: Beheben Sie sie, bevor Sie das Programm vorbereiten.</translation>
    </message>
    <message>
        <source>1-6, or none</source>
        <translation>1-6 oder none</translation>
    </message>
    <message>
        <source>&amp;Rack holds:</source>
        <translation>&amp;Magazin enthält:</translation>
    </message>
    <message>
        <source>Only the first %1 tools are listed; the other %2 are counted, their findings summed up one for each kind.</source>
        <translation>Nur die ersten %1 Werkzeuge sind aufgeführt; die übrigen %2 sind gezählt, ihre Befunde zu einem je Art zusammengefasst.</translation>
    </message>
</context>
<context>
    <name>Toffee::JobChecker</name>
    <message>
        <source>A feed move before any tool change: the program does not say which tool is in the spindle.</source>
        <translation>Eine Vorschubbewegung vor jedem Werkzeugwechsel: Das Programm sagt nicht, welches Werkzeug in der Spindel ist.</translation>
    </message>
    <message>
        <source>T%1 feeds to work Z %2, below the floor of %3.</source>
        <translation>T%1 fährt im Vorschub auf Werkstück-Z %2, unter die Untergrenze von %3.</translation>
    </message>
    <message>
        <source>A feed move to work Z %1, below the floor of %2.</source>
        <translation>Eine Vorschubbewegung auf Werkstück-Z %1, unter die Untergrenze von %2.</translation>
    </message>
    <message>
        <source>T%1 cuts with no length compensation: no G43 since it was loaded.</source>
        <translation>T%1 schneidet ohne Werkzeuglängenkorrektur: kein G43, seit es eingewechselt wurde.</translation>
    </message>
    <message>
        <source>T%1 cuts with %2%3 still in force from the tool before: no G43 %2%1 since its change.</source>
        <translation>T%1 schneidet mit %2%3, das noch vom vorigen Werkzeug gilt: kein G43 %2%1 seit seinem Wechsel.</translation>
    </message>
    <message>
        <source>T%1 cuts with the length offset %2%3, which is another tool&apos;s.</source>
        <translation>T%1 schneidet mit der Längenkorrektur %2%3, die zu einem anderen Werkzeug gehört.</translation>
    </message>
    <message>
        <source>The program sets T%1&apos;s TLO to %2 itself; the table holds %3 for it.</source>
        <translation>Das Programm setzt die TLO von T%1 selbst auf %2; die Tabelle hat %3 dafür.</translation>
    </message>
    <message>
        <source>G20: the Carvera refuses inch programs (ALARM: Imperial Units are unsupported). Post the program in millimetres.</source>
        <translation>G20: Die Carvera lehnt Zollprogramme ab (ALARM: Imperial Units are unsupported). Geben Sie das Programm im Postprozessor in Millimetern aus.</translation>
    </message>
    <message>
        <source>The program is in inches (G20) but the tool table is in millimetres.</source>
        <translation>Das Programm ist in Zoll (G20), die Werkzeugtabelle aber in Millimetern.</translation>
    </message>
    <message>
        <source>The program is in millimetres (G21) but the tool table is in inches.</source>
        <translation>Das Programm ist in Millimetern (G21), die Werkzeugtabelle aber in Zoll.</translation>
    </message>
    <message>
        <source>More lines the controller would refuse, from this one on: %1 in all.</source>
        <translation>Weitere Zeilen, die die Steuerung ablehnen würde, ab dieser: insgesamt %1.</translation>
    </message>
    <message>
        <source>The machine&apos;s rack does not hold T%1: it is a manual change, and the machine waits for the operator.</source>
        <translation>Das Magazin der Maschine enthält T%1 nicht: Es ist ein manueller Wechsel, und die Maschine wartet auf den Bediener.</translation>
    </message>
    <message>
        <source>T%1 is not in the tool table: nothing is known of its length.</source>
        <translation>T%1 steht nicht in der Werkzeugtabelle: Über seine Länge ist nichts bekannt.</translation>
    </message>
    <message>
        <source>T%1 failed its last break test and has not been measured since: check the tool and probe it.</source>
        <translation>T%1 hat seinen letzten Bruchtest nicht bestanden und wurde seitdem nicht gemessen: Prüfen Sie das Werkzeug und vermessen Sie es.</translation>
    </message>
    <message>
        <source>T%1 has no measured TLO.</source>
        <translation>T%1 hat keine gemessene TLO.</translation>
    </message>
    <message>
        <source>T%1 has no length in the table: G43 would apply 0.</source>
        <translation>T%1 hat keine Länge in der Tabelle: G43 würde 0 anwenden.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO is dated %2, in the future: a clock was wrong, and when it was measured is not known.</source>
        <translation>Die TLO von T%1 ist auf %2 datiert, in der Zukunft: Eine Uhr ging falsch, und wann sie gemessen wurde, ist unbekannt.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was measured %2, before the stale limit (%3 d).</source>
        <translation>Die TLO von T%1 wurde %2 gemessen und ist veraltet (Grenze %3 d).</translation>
    </message>
    <message>
        <source>The history has a newer measurement of T%1 (%2, %3) than the table&apos;s: the table was not saved after it.</source>
        <translation>Der Verlauf hat eine neuere Messung von T%1 (%2, %3) als die Tabelle: Die Tabelle wurde danach nicht gespeichert.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was set by hand, not measured on the tool setter: probe it before the job.</source>
        <translation>Die TLO von T%1 wurde von Hand gesetzt, nicht am Werkzeugtaster gemessen: vor dem Job antasten.</translation>
    </message>
    <message>
        <source>%1 more tools the table lacks</source>
        <translation>%1 weitere Werkzeuge, die nicht in der Tabelle stehen</translation>
    </message>
    <message>
        <source>%1 more tools the machine&apos;s rack does not hold (manual changes)</source>
        <translation>%1 weitere Werkzeuge, die das Magazin der Maschine nicht enthält (manuelle Wechsel)</translation>
    </message>
    <message>
        <source>%1 more tools with no TLO measured on the tool setter</source>
        <translation>%1 weitere Werkzeuge ohne am Werkzeugtaster gemessene TLO</translation>
    </message>
    <message>
        <source>%1 more tools whose TLO is older than the stale limit (%2 d) or dated in the future</source>
        <translation>%1 weitere Werkzeuge, deren TLO älter als die Grenze (%2 d) oder in die Zukunft datiert ist</translation>
    </message>
    <message>
        <source>%1 more tools that failed their last break test</source>
        <translation>%1 weitere Werkzeuge, die ihren letzten Bruchtest nicht bestanden haben</translation>
    </message>
    <message>
        <source>%1 more tools feed below the floor of %2</source>
        <translation>%1 weitere Werkzeuge fahren im Vorschub unter die Untergrenze von %2</translation>
    </message>
    <message>
        <source>%1 more tools cut with no length compensation</source>
        <translation>%1 weitere Werkzeuge schneiden ohne Werkzeuglängenkorrektur</translation>
    </message>
    <message>
        <source>%1 more tools cut with another tool&apos;s length offset</source>
        <translation>%1 weitere Werkzeuge schneiden mit der Längenkorrektur eines anderen Werkzeugs</translation>
    </message>
    <message>
        <source>%1 more tools have their TLO set by the program to another value than the table&apos;s</source>
        <translation>Bei %1 weiteren Werkzeugen setzt das Programm die TLO auf einen anderen Wert als die Tabelle</translation>
    </message>
    <message>
        <source>%1, beyond the first %2 tools the program loads; the first of them is T%3. Counted, not listed, and judged by the table alone: the history library is read for the listed tools only.</source>
        <translation>%1, über die ersten %2 Werkzeuge hinaus, die das Programm einwechselt; das erste davon ist T%3. Gezählt, nicht aufgeführt und allein nach der Tabelle beurteilt: Die Verlaufsbibliothek wird nur für die aufgeführten Werkzeuge gelesen.</translation>
    </message>
    <message>
        <source>%1, beyond the first %2 tools the program loads; the first of them is T%3. Counted, not listed.</source>
        <translation>%1, über die ersten %2 Werkzeuge hinaus, die das Programm einwechselt; das erste davon ist T%3. Gezählt, nicht aufgeführt.</translation>
    </message>
    <message>
        <source>The controller&apos;s own table has no T%1: G43 H%1 is refused. Renumber the tool, or apply its TLO with G43.1.</source>
        <translation>Die eigene Tabelle der Steuerung hat kein T%1: G43 H%1 wird abgelehnt. Nummerieren Sie das Werkzeug um oder wenden Sie seine TLO mit G43.1 an.</translation>
    </message>
    <message>
        <source>The controller&apos;s own table holds %1 for T%2, the table file %3: G43 H%2 would apply the controller&apos;s. Push the offsets (Machine ▸ Push Offsets…, toffee-cli push-offsets) or probe T%2 before the job.</source>
        <translation>Die eigene Tabelle der Steuerung hat für T%2 den Wert %1, die Tabellendatei %3: G43 H%2 würde den der Steuerung anwenden. Übertragen Sie die Korrekturen (Maschine ▸ Korrekturen an die Steuerung übertragen …, toffee-cli push-offsets) oder vermessen Sie T%2 vor dem Job.</translation>
    </message>
    <message>
        <source>%1 more tools whose TLO in the controller&apos;s own table is not the file&apos;s</source>
        <translation>%1 weitere Werkzeuge, deren TLO in der eigenen Tabelle der Steuerung nicht der in der Datei entspricht</translation>
    </message>
    <message>
        <source>T%1 would pass its life limit of %2 min in this program: its cutter has cut %3 since it went in, and the program cuts %4 more. Put in a new cutter (Edit ▸ New Cutter…, toffee-cli new-cutter %1) or raise the limit.</source>
        <translation>T%1 würde in diesem Programm seine Standzeit von %2 min überschreiten: Sein Fräser hat seit dem Einsetzen %3 zerspant, und das Programm zerspant %4 mehr. Setzen Sie einen neuen Fräser ein (Bearbeiten ▸ Neuer Fräser …, toffee-cli new-cutter %1) oder erhöhen Sie die Standzeit.</translation>
    </message>
    <message>
        <source>T%1 would pass its life limit of %2 uses: its cutter has cut in %3 programs since it went in, and this is one more. Put in a new cutter (Edit ▸ New Cutter…, toffee-cli new-cutter %1) or raise the limit.</source>
        <translation>T%1 würde seine Standzeit von %2 Einsätzen überschreiten: Sein Fräser hat seit dem Einsetzen in %3 Programmen zerspant, und dies ist eines mehr. Setzen Sie einen neuen Fräser ein (Bearbeiten ▸ Neuer Fräser …, toffee-cli new-cutter %1) oder erhöhen Sie die Standzeit.</translation>
    </message>
    <message>
        <source>The history says T%1 got a new cutter %2, after the table&apos;s TLO was measured: that TLO is the old cutter&apos;s. Probe T%1 before the job.</source>
        <translation>Laut Verlauf hat T%1 %2 einen neuen Fräser bekommen, nachdem die TLO der Tabelle gemessen wurde: Diese TLO ist die des alten Fräsers. Vermessen Sie T%1 vor dem Auftrag.</translation>
    </message>
    <message>
        <source>T%1 is past its life limit of %2 min already: its cutter has cut %3 since it went in, and the program cuts %4 more. Put in a new cutter (Edit ▸ New Cutter…, toffee-cli new-cutter %1) or raise the limit.</source>
        <translation>T%1 hat seine Standzeit von %2 min bereits überschritten: Sein Fräser hat seit dem Einsetzen %3 zerspant, und das Programm zerspant %4 mehr. Setzen Sie einen neuen Fräser ein (Bearbeiten ▸ Neuer Fräser …, toffee-cli new-cutter %1) oder erhöhen Sie die Standzeit.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was read from the controller&apos;s table, not measured on the tool setter: probe it before the job.</source>
        <translation>Die TLO von T%1 wurde aus der Tabelle der Steuerung gelesen, nicht am Werkzeugtaster gemessen: Messen Sie T%1 vor dem Auftrag.</translation>
    </message>
    <message>
        <source>T%1&apos;s edges differed by %2 when it was last measured, more than its limit %3: runout or a chipped edge. Look at the cutter and how it sits in its holder before it cuts.</source>
        <translation>Die Schneiden von T%1 lagen bei der letzten Messung %2 auseinander, mehr als ihre Grenze %3: Rundlauffehler oder eine ausgebrochene Schneide. Prüfen Sie den Fräser und seinen Sitz im Halter, bevor er schneidet.</translation>
    </message>
</context>
<context>
    <name>Toffee::JobFindingsModel</name>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <source>%1 (%2 times: lines %3)</source>
        <translation>%1 (%2-mal: Zeilen %3)</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>Schweregrad</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Zeile</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>Finding</source>
        <translation>Befund</translation>
    </message>
    <message>
        <source>%1 tools</source>
        <translation>%1 Werkzeuge</translation>
    </message>
</context>
<context>
    <name>Toffee::JobPrepareDialog</name>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>&amp;Save Prepared Program…</source>
        <translation>Vorbereitetes Programm &amp;speichern …</translation>
    </message>
    <message>
        <source>Prepare %1 for %2</source>
        <translation>%1 für %2 vorbereiten</translation>
    </message>
    <message>
        <source>After a manual change, set the tool&apos;s stored TLO instead of probing, when it is within the stale limit (%1 d)</source>
        <translation>Nach einem manuellen Wechsel die gespeicherte TLO des Werkzeugs setzen statt zu vermessen, wenn sie nicht veraltet ist (%1 d)</translation>
    </message>
    <message>
        <source>Break-test each tool after its last cut, with the tolerance</source>
        <translation>Bruchtest für jedes Werkzeug nach seinem letzten Schnitt, mit der Toleranz</translation>
    </message>
    <message>
        <source>Break-test tolerance</source>
        <translation>Toleranz des Bruchtests</translation>
    </message>
    <message>
        <source>%1: the missing G43 after each tool change is inserted, and nothing else.</source>
        <translation>%1: Das fehlende G43 nach jedem Werkzeugwechsel wird eingefügt, sonst nichts.</translation>
    </message>
    <message>
        <source>The original and the prepared program, side by side</source>
        <translation>Das ursprüngliche und das vorbereitete Programm nebeneinander</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>Zeile</translation>
    </message>
    <message>
        <source>Original</source>
        <translation>Original</translation>
    </message>
    <message>
        <source>Prepared</source>
        <translation>Vorbereitet</translation>
    </message>
    <message>
        <source>Preparing the preview…</source>
        <translation>Vorschau wird erstellt …</translation>
    </message>
    <message>
        <source>Writing %1…</source>
        <translation>%1 wird geschrieben …</translation>
    </message>
    <message>
        <source>Cancelled: nothing was written.</source>
        <translation>Abgebrochen: Es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>Nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>The program cannot be prepared: %1</source>
        <translation>Das Programm lässt sich nicht vorbereiten: %1</translation>
    </message>
    <message>
        <source>Written to %1.</source>
        <translation>In %1 geschrieben.</translation>
    </message>
    <message>
        <source>Nothing to change: the program already does what these options ask.</source>
        <translation>Nichts zu ändern: Das Programm tut bereits, was diese Optionen verlangen.</translation>
    </message>
    <message>
        <source>Lines inserted: %1, changed: %2. Cutting moves checked against the original: %3; each reaches the same work position with its tool&apos;s own offset.</source>
        <translation>Eingefügte Zeilen: %1, geänderte: %2. Gegen das Original geprüfte Schnittbewegungen: %3; jede erreicht dieselbe Werkstückposition mit der eigenen Korrektur ihres Werkzeugs.</translation>
    </message>
    <message>
        <source>The preview shows the first %1 changes; the other %2 are not shown.</source>
        <translation>Die Vorschau zeigt die ersten %1 Änderungen; die übrigen %2 werden nicht gezeigt.</translation>
    </message>
    <message>
        <source>Save Prepared Program</source>
        <translation>Vorbereitetes Programm speichern</translation>
    </message>
    <message>
        <source>G-code programs (*.nc *.gcode *.ngc *.tap *.cnc);;All files (*)</source>
        <translation>G-Code-Programme (*.nc *.gcode *.ngc *.tap *.cnc);;Alle Dateien (*)</translation>
    </message>
</context>
<context>
    <name>Toffee::JobPreparer</name>
    <message>
        <source>%1 has no stored-offset or break-test commands: --use-stored-tlo and --break-test are for the Carvera. For %1, prepare inserts only the missing G43.</source>
        <translation>%1 hat keine Befehle für gespeicherte Korrekturen oder Bruchtests: --use-stored-tlo und --break-test sind für die Carvera. Für %1 fügt die Vorbereitung nur das fehlende G43 ein.</translation>
    </message>
    <message>
        <source>Preparing a program is for the Carvera and the controllers with G43; Automation1 compensates with G143 / G144, which Toffee does not insert.</source>
        <translation>Das Vorbereiten eines Programms ist für die Carvera und die Steuerungen mit G43; Automation1 korrigiert mit G143 / G144, die Toffee nicht einfügt.</translation>
    </message>
    <message>
        <source>Say what to prepare: --use-stored-tlo, --break-test, or both.</source>
        <translation>Geben Sie an, was vorbereitet werden soll: --use-stored-tlo, --break-test oder beides.</translation>
    </message>
    <message>
        <source>The break-test tolerance must be from %1 mm (the Carvera halts below it) to %2 mm (a looser test would miss a broken tool).</source>
        <translation>Die Bruchtest-Toleranz muss zwischen %1 mm (darunter hält die Carvera an) und %2 mm liegen (ein lockererer Test würde ein gebrochenes Werkzeug übersehen).</translation>
    </message>
    <message>
        <source>%1 Toffee prepares only a program the controller runs: check the job first.</source>
        <translation>%1 Toffee bereitet nur ein Programm vor, das die Steuerung ausführt: Prüfen Sie zuerst den Job.</translation>
    </message>
    <message>
        <source>the line Toffee would insert here, &quot;%1&quot;, is refused: %2 Nothing was written.</source>
        <translation>Die Zeile, die Toffee hier einfügen würde, „%1“, wird abgelehnt: %2 Es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>the line Toffee would insert here, &quot;%1&quot;, would move the machine. Nothing was written.</source>
        <translation>Die Zeile, die Toffee hier einfügen würde, „%1“, würde die Maschine bewegen. Es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>the prepared program could not be written.</source>
        <translation>Das vorbereitete Programm ließ sich nicht schreiben.</translation>
    </message>
    <message>
        <source>the prepared line &quot;%1&quot; is refused: %2 Nothing was written.</source>
        <translation>Die vorbereitete Zeile „%1“ wird abgelehnt: %2 Es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>The program cuts before any tool change (original line %1): there is no tool to break-test.</source>
        <translation>Das Programm schneidet vor jedem Werkzeugwechsel (Originalzeile %1): Es gibt kein Werkzeug für einen Bruchtest.</translation>
    </message>
    <message>
        <source>T%1 is in the rack: the Carvera measures a rack tool at every change.</source>
        <translation>T%1 ist im Magazin: Die Carvera vermisst ein Magazinwerkzeug bei jedem Wechsel.</translation>
    </message>
    <message>
        <source>the prepared program would put the machine elsewhere than the original with the table&apos;s offsets. Nothing was written.</source>
        <translation>Das vorbereitete Programm würde die Maschine mit den Korrekturen der Tabelle an eine andere Stelle bringen als das Original. Es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>the prepared program would cut at another work position than the original. Nothing was written.</source>
        <translation>Das vorbereitete Programm würde an einer anderen Werkstückposition schneiden als das Original. Es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>the prepared program would cut without T%1&apos;s length offset. Nothing was written.</source>
        <translation>Das vorbereitete Programm würde ohne die Längenkorrektur von T%1 schneiden. Es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO does not say which reference it was measured against: check that it still holds.</source>
        <translation>Die gespeicherte TLO von T%1 sagt nicht, gegen welche Referenz sie gemessen wurde: Prüfen Sie, ob sie noch stimmt.</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO was measured against reference MCS Z %2 and T%3&apos;s against %4: the machine has one reference, so at most one is right. Probe one of them again, or prepare without stored TLOs. Nothing was written.</source>
        <translation>Die gespeicherte TLO von T%1 wurde gegen Referenz-MCS-Z %2 gemessen, die von T%3 gegen %4: Die Maschine hat eine Referenz, also stimmt höchstens eine. Vermessen Sie eines der Werkzeuge erneut oder bereiten Sie ohne gespeicherte TLOs vor. Es wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>%1 more notes like these, one for each further tool (the first of them T%2): counted, not listed.</source>
        <translation>%1 weitere solche Hinweise, einer je weiteres Werkzeug (das erste davon T%2): gezählt, nicht aufgeführt.</translation>
    </message>
    <message>
        <source>The stored TLOs hold only while the machine&apos;s reference MCS Z is %1 (its calibration): check it before running the program.</source>
        <translation>Die gespeicherten Längenkorrekturen gelten nur, solange die Referenz-MCS-Z der Maschine %1 ist (ihre Kalibrierung): Prüfen Sie das, bevor Sie das Programm starten.</translation>
    </message>
</context>
<context>
    <name>Toffee::JobReport</name>
    <message>
        <source>no findings</source>
        <translation>keine Befunde</translation>
    </message>
    <message>
        <source>1 error</source>
        <translation>1 Fehler</translation>
    </message>
    <message>
        <source>%1 errors</source>
        <translation>%1 Fehler</translation>
    </message>
    <message>
        <source>1 warning</source>
        <translation>1 Warnung</translation>
    </message>
    <message>
        <source>%1 warnings</source>
        <translation>%1 Warnungen</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1, %2</translation>
    </message>
</context>
<context>
    <name>Toffee::JobToolsModel</name>
    <message>
        <source>not in the table</source>
        <translation>nicht in der Tabelle</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>nicht gemessen</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>Loaded at line</source>
        <translation>Eingewechselt in Zeile</translation>
    </message>
    <message>
        <source>TLO (mm)</source>
        <translation>TLO (mm)</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Gemessen</translation>
    </message>
    <message>
        <source>Cutting time</source>
        <translation>Schnittzeit</translation>
    </message>
    <message>
        <source>Feed path (mm)</source>
        <translation>Vorschubweg (mm)</translation>
    </message>
    <message>
        <source>Lowest cut Z (mm)</source>
        <translation>Tiefstes Schnitt-Z (mm)</translation>
    </message>
    <message>
        <source>%1 (by hand)</source>
        <translation>%1 (von Hand)</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>gesetzt %1</translation>
    </message>
    <message>
        <source>%1 more</source>
        <translation>%1 weitere</translation>
    </message>
    <message>
        <source>from line %1, %2 loads: counted, not listed</source>
        <translation>ab Zeile %1, %2 Wechsel: gezählt, nicht aufgeführt</translation>
    </message>
    <message>
        <source>The program loads %1 distinct tools: the first %2 are listed, the other %3 only counted. Their findings are summed up, one for each kind.</source>
        <translation>Das Programm wechselt %1 verschiedene Werkzeuge ein: Die ersten %2 sind aufgeführt, die übrigen %3 nur gezählt. Ihre Befunde sind zusammengefasst, einer je Art.</translation>
    </message>
</context>
<context>
    <name>Toffee::JsonScanner</name>
    <message>
        <source>this is not valid JSON: expected %1.</source>
        <translation>Das ist kein gültiges JSON: erwartet wurde %1.</translation>
    </message>
    <message>
        <source>this is not valid JSON: a line break or control character inside a string; write it as \n.</source>
        <translation>Das ist kein gültiges JSON: ein Zeilenumbruch oder Steuerzeichen in einer Zeichenkette; schreiben Sie ihn als \n.</translation>
    </message>
    <message>
        <source>this is not valid JSON: a lone UTF-16 surrogate in a \u escape.</source>
        <translation>Das ist kein gültiges JSON: ein einzelnes UTF-16-Surrogat in einer \u-Sequenz.</translation>
    </message>
    <message>
        <source>this is not valid JSON: unknown escape \%1 in a string.</source>
        <translation>Das ist kein gültiges JSON: unbekannte Escape-Sequenz \%1 in einer Zeichenkette.</translation>
    </message>
    <message>
        <source>this is not valid JSON: a string is never closed.</source>
        <translation>Das ist kein gültiges JSON: Eine Zeichenkette wird nie geschlossen.</translation>
    </message>
    <message>
        <source>the number %1 is too large.</source>
        <translation>Die Zahl %1 ist zu groß.</translation>
    </message>
    <message>
        <source>this is not valid JSON: a \u escape needs four hex digits.</source>
        <translation>Das ist kein gültiges JSON: Eine \u-Sequenz braucht vier Hexadezimalziffern.</translation>
    </message>
    <message>
        <source>a string is not valid UTF-8 text.</source>
        <translation>Eine Zeichenkette ist kein gültiger UTF-8-Text.</translation>
    </message>
    <message>
        <source>the text &quot;%1&quot; is longer than %2 KB; no field of a tool table holds that much.</source>
        <translation>Der Text „%1“ ist länger als %2 KB; kein Feld einer Werkzeugtabelle fasst so viel.</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; appears twice at the top level; Toffee will not guess which one is meant.</source>
        <translation>Der Schlüssel „%1“ kommt auf der obersten Ebene zweimal vor; Toffee rät nicht, welcher gemeint ist.</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; appears twice in one object; Toffee will not guess which one is meant.</source>
        <translation>Der Schlüssel „%1“ kommt in einem Objekt zweimal vor; Toffee rät nicht, welcher gemeint ist.</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; appears twice in &quot;%2&quot;; Toffee will not guess which one is meant.</source>
        <translation>Der Schlüssel „%1“ kommt in „%2“ zweimal vor; Toffee rät nicht, welcher gemeint ist.</translation>
    </message>
    <message>
        <source>this is not JSON Toffee reads: it is nested too deeply (more than %1 levels).</source>
        <translation>Das ist kein JSON, das Toffee liest: Es ist zu tief verschachtelt (mehr als %1 Ebenen).</translation>
    </message>
</context>
<context>
    <name>Toffee::Library</name>
    <message>
        <source>Adding the machine %1</source>
        <translation>Das Hinzufügen der Maschine %1</translation>
    </message>
    <message>
        <source>Reading the machines</source>
        <translation>Das Lesen der Maschinen</translation>
    </message>
    <message>
        <source>Recording T%1&apos;s %2</source>
        <translation>Das Aufzeichnen von T%1 (%2)</translation>
    </message>
    <message>
        <source>Recording T%1&apos;s use</source>
        <translation>Das Aufzeichnen der Nutzung von T%1</translation>
    </message>
    <message>
        <source>Reading the history</source>
        <translation>Das Lesen des Verlaufs</translation>
    </message>
    <message>
        <source>Reading the tools&apos; use</source>
        <translation>Das Lesen der Werkzeugnutzung</translation>
    </message>
    <message>
        <source>%1 is a folder, not a library file. Choose a file in it, such as %2.</source>
        <translation>%1 ist ein Ordner, keine Bibliotheksdatei. Wählen Sie eine Datei darin, etwa %2.</translation>
    </message>
    <message>
        <source>%1 is not a regular file: a library is an SQLite file.</source>
        <translation>%1 ist keine gewöhnliche Datei: Eine Bibliothek ist eine SQLite-Datei.</translation>
    </message>
    <message>
        <source>%1 is not a Toffee library: it is not an SQLite database. Choose another file, or move this one away.</source>
        <translation>%1 ist keine Toffee-Bibliothek: Es ist keine SQLite-Datenbank. Wählen Sie eine andere Datei oder verschieben Sie diese.</translation>
    </message>
    <message>
        <source>The folder of %1 cannot be created.</source>
        <translation>Der Ordner von %1 lässt sich nicht anlegen.</translation>
    </message>
    <message>
        <source>Qt&apos;s SQLite driver is missing: install libqt6sql6-sqlite.</source>
        <translation>Qts SQLite-Treiber fehlt: Installieren Sie libqt6sql6-sqlite.</translation>
    </message>
    <message>
        <source>%1 cannot be opened: %2</source>
        <translation>%1 lässt sich nicht öffnen: %2</translation>
    </message>
    <message>
        <source>%1: %2 failed: %3</source>
        <translation>%1: %2 ist fehlgeschlagen: %3</translation>
    </message>
    <message>
        <source>%1 is damaged or is not a library: %2. Move it away (Toffee then starts a new one), or choose another file.</source>
        <translation>%1 ist beschädigt oder keine Bibliothek: %2. Verschieben Sie die Datei (Toffee legt dann eine neue an) oder wählen Sie eine andere.</translation>
    </message>
    <message>
        <source>%1 was written by a newer Toffee (library version %2; this Toffee knows up to %3). It was not changed: use a newer Toffee with it, or choose another library.</source>
        <translation>%1 wurde von einem neueren Toffee geschrieben (Bibliotheksversion %2; dieses Toffee kennt bis %3). Sie wurde nicht verändert: Verwenden Sie ein neueres Toffee dafür oder wählen Sie eine andere Bibliothek.</translation>
    </message>
    <message>
        <source>Reading the library</source>
        <translation>Das Lesen der Bibliothek</translation>
    </message>
    <message>
        <source>Reading the library&apos;s version</source>
        <translation>Das Lesen der Bibliotheksversion</translation>
    </message>
    <message>
        <source>Creating the library</source>
        <translation>Das Anlegen der Bibliothek</translation>
    </message>
    <message>
        <source>Bringing the library to version %1</source>
        <translation>Das Aktualisieren der Bibliothek auf Version %1</translation>
    </message>
    <message>
        <source>Bringing the library up to date</source>
        <translation>Das Aktualisieren der Bibliothek</translation>
    </message>
    <message>
        <source>your login name</source>
        <translation>Ihr Anmeldename</translation>
    </message>
    <message>
        <source>The server refused %1&apos;s password. Put the right one in the PostgreSQL password file (~/.pgpass, or the file PGPASSFILE names): Toffee never stores one.</source>
        <translation>Der Server hat das Passwort abgelehnt (Benutzer: %1). Tragen Sie das richtige in die PostgreSQL-Passwortdatei ein (~/.pgpass oder die Datei, die PGPASSFILE nennt): Toffee speichert nie ein Passwort.</translation>
    </message>
    <message>
        <source>The server has no database &quot;%1&quot;. Check the name in the URL, or have it created (createdb %1; docs/LIBRARY.md).</source>
        <translation>Der Server hat keine Datenbank „%1“. Prüfen Sie den Namen in der URL oder lassen Sie sie anlegen (createdb %1; docs/LIBRARY.md).</translation>
    </message>
    <message>
        <source>The server has no user &quot;%1&quot;. Check the user in the URL, or have the role created (docs/LIBRARY.md).</source>
        <translation>Der Server hat keinen Benutzer „%1“. Prüfen Sie den Benutzer in der URL oder lassen Sie die Rolle anlegen (docs/LIBRARY.md).</translation>
    </message>
    <message>
        <source>The server&apos;s name &quot;%1&quot; is not known here. Check the host in the URL.</source>
        <translation>Der Servername „%1“ ist hier nicht bekannt. Prüfen Sie den Host in der URL.</translation>
    </message>
    <message>
        <source>The connection&apos;s encryption failed. Check sslmode in the URL against the server&apos;s settings.</source>
        <translation>Die Verschlüsselung der Verbindung ist fehlgeschlagen. Gleichen Sie sslmode in der URL mit den Einstellungen des Servers ab.</translation>
    </message>
    <message>
        <source>The server cannot be reached. Check that it is running and that the host and port in the URL are right.</source>
        <translation>Der Server ist nicht erreichbar. Prüfen Sie, ob er läuft und ob Host und Port in der URL stimmen.</translation>
    </message>
    <message>
        <source>The library (%1) cannot be opened. %2 (The server said: %3)</source>
        <translation>Die Bibliothek (%1) lässt sich nicht öffnen. %2 (Der Server meldete: %3)</translation>
    </message>
    <message>
        <source>Qt&apos;s PostgreSQL driver is missing: install libqt6sql6-psql to use %1.</source>
        <translation>Qts PostgreSQL-Treiber fehlt: Installieren Sie libqt6sql6-psql, um %1 zu verwenden.</translation>
    </message>
    <message>
        <source>Reading the server&apos;s version</source>
        <translation>Das Lesen der Serverversion</translation>
    </message>
    <message>
        <source>The library (%1) is on PostgreSQL %2, which this Toffee does not support: it needs %3 or newer. Upgrade the server, or use another one.</source>
        <translation>Die Bibliothek (%1) liegt auf PostgreSQL %2, das dieses Toffee nicht unterstützt: Es braucht %3 oder neuer. Aktualisieren Sie den Server oder verwenden Sie einen anderen.</translation>
    </message>
    <message>
        <source>Reading your rights in the library</source>
        <translation>Das Lesen Ihrer Rechte in der Bibliothek</translation>
    </message>
    <message>
        <source>%1 is a database, but not a Toffee library (it has tables of its own). Choose another one.</source>
        <translation>%1 ist eine Datenbank, aber keine Toffee-Bibliothek (sie hat eigene Tabellen). Wählen Sie eine andere.</translation>
    </message>
    <message>
        <source>The library (%1) is read-only for %2: this role may read the tools but not change them. Ask whoever runs the server for write rights (docs/LIBRARY.md).</source>
        <translation>Die Bibliothek (%1) ist für %2 schreibgeschützt: Diese Rolle darf die Werkzeuge lesen, aber nicht ändern. Bitten Sie den Betreiber des Servers um Schreibrechte (docs/LIBRARY.md).</translation>
    </message>
    <message>
        <source>you</source>
        <translation>Sie</translation>
    </message>
    <message>
        <source>%1 is read-only: it cannot be written.</source>
        <translation>%1 ist schreibgeschützt und lässt sich nicht schreiben.</translation>
    </message>
    <message>
        <source>Announcing the change</source>
        <translation>Das Ankündigen der Änderung</translation>
    </message>
    <message>
        <source>Reading the machine tables</source>
        <translation>Das Lesen der Maschinentabellen</translation>
    </message>
    <message>
        <source>Reading %1&apos;s table</source>
        <translation>Das Lesen der Tabelle von %1</translation>
    </message>
    <message>
        <source>The library has no tool table for %1.</source>
        <translation>Die Bibliothek hat keine Werkzeugtabelle für %1.</translation>
    </message>
    <message>
        <source>Reading T%1 of %2</source>
        <translation>Das Lesen von T%1 aus der Tabelle von %2</translation>
    </message>
    <message>
        <source>Writing T%1 of %2</source>
        <translation>Das Schreiben von T%1 in die Tabelle von %2</translation>
    </message>
    <message>
        <source>Adding %1&apos;s table</source>
        <translation>Das Hinzufügen der Tabelle von %1</translation>
    </message>
    <message>
        <source>The library already has a tool table for %1: open it, or choose another name.</source>
        <translation>Die Bibliothek hat bereits eine Werkzeugtabelle für %1: Öffnen Sie sie oder wählen Sie einen anderen Namen.</translation>
    </message>
    <message>
        <source>T%1 of %2 kept changing while it was written.</source>
        <translation>T%1 der Tabelle von %2 hat sich beim Schreiben immer wieder geändert.</translation>
    </message>
    <message>
        <source>Keeping a change for later</source>
        <translation>Das Aufbewahren einer Änderung für später</translation>
    </message>
    <message>
        <source>Reading the changes kept for later</source>
        <translation>Das Lesen der für später aufbewahrten Änderungen</translation>
    </message>
    <message>
        <source>Clearing a change written</source>
        <translation>Das Löschen einer geschriebenen Änderung</translation>
    </message>
    <message>
        <source>A tool&apos;s row does not hold one tool in its table&apos;s units.</source>
        <translation>Die Zeile eines Werkzeugs enthält nicht genau ein Werkzeug in den Einheiten seiner Tabelle.</translation>
    </message>
    <message>
        <source>An outbox entry cannot be read; it is kept as it is.</source>
        <translation>Ein Eintrag im Postausgang lässt sich nicht lesen; er bleibt unverändert erhalten.</translation>
    </message>
    <message>
        <source>The library (%1) was busy: another station or program held what Toffee needed (%2) for more than %3 s, Toffee&apos;s limit.</source>
        <translation>Die Bibliothek (%1) war belegt: Eine andere Station oder ein anderes Programm hielt, was Toffee brauchte (%2), länger als %3 s, die Grenze von Toffee.</translation>
    </message>
    <message>
        <source>a table or column Toffee needs is missing (%1)</source>
        <translation>eine Tabelle oder Spalte, die Toffee braucht, fehlt (%1)</translation>
    </message>
    <message>
        <source>the database gave no reason</source>
        <translation>die Datenbank nannte keinen Grund</translation>
    </message>
    <message>
        <source>Starting a write</source>
        <translation>Das Beginnen eines Schreibvorgangs</translation>
    </message>
    <message>
        <source>Setting how long to wait</source>
        <translation>Das Festlegen der Wartezeit</translation>
    </message>
    <message>
        <source>Writing</source>
        <translation>Das Schreiben</translation>
    </message>
    <message>
        <source>%1 is damaged: %2. Toffee leaves it as it is and writes nothing into it: restore it from a backup (docs/LIBRARY.md), or choose another library.</source>
        <translation>%1 ist beschädigt: %2. Toffee lässt sie unverändert und schreibt nichts hinein: Stellen Sie sie aus einer Sicherung wieder her (docs/LIBRARY.md) oder wählen Sie eine andere Bibliothek.</translation>
    </message>
    <message>
        <source>its table &quot;%1&quot; is missing</source>
        <translation>ihre Tabelle „%1“ fehlt</translation>
    </message>
    <message>
        <source>its table &quot;%1&quot; was altered: it has no column &quot;%2&quot;</source>
        <translation>ihre Tabelle „%1“ wurde verändert: Sie hat keine Spalte „%2“</translation>
    </message>
    <message>
        <source>its version table (toffee_schema) is empty, so it cannot say which Toffee wrote it</source>
        <translation>ihre Versionstabelle (toffee_schema) ist leer, sie kann also nicht sagen, welches Toffee sie schrieb</translation>
    </message>
    <message>
        <source>its version table (toffee_schema) holds more than one version</source>
        <translation>ihre Versionstabelle (toffee_schema) enthält mehr als eine Version</translation>
    </message>
    <message>
        <source>its schema version is &quot;%1&quot;, which is not a version any Toffee writes</source>
        <translation>ihre Schemaversion ist „%1“, eine Version, die kein Toffee schreibt</translation>
    </message>
    <message>
        <source>%1: %2&apos;s table says its units are %3, neither mm nor in; it was written by another program or by hand, and is not opened.</source>
        <translation>%1: Die Tabelle von %2 nennt die Einheiten %3, weder mm noch in; sie wurde von einem anderen Programm oder von Hand geschrieben und wird nicht geöffnet.</translation>
    </message>
    <message>
        <source>%1: %2&apos;s table has rows Toffee cannot read, so it is not opened and nothing was written: %3. They were written by another program or by hand; put the table back from a backup, or have whoever changed them correct them (docs/LIBRARY.md).</source>
        <translation>%1: Die Tabelle von %2 hat Zeilen, die Toffee nicht lesen kann; sie wird daher nicht geöffnet, und nichts wurde geschrieben: %3. Sie wurden von einem anderen Programm oder von Hand geschrieben; stellen Sie die Tabelle aus einer Sicherung wieder her oder lassen Sie sie von dem korrigieren, der sie geändert hat (docs/LIBRARY.md).</translation>
    </message>
    <message>
        <source>%1: %2&apos;s table has units %3, neither mm nor in.</source>
        <translation>%1: Die Tabelle von %2 hat die Einheiten %3, weder mm noch in.</translation>
    </message>
    <message>
        <source>%1: %2&apos;s %3. Nothing was written to it.</source>
        <translation>%1: Tabelle von %2, %3. Nichts wurde hineingeschrieben.</translation>
    </message>
    <message>
        <source>and %1 more</source>
        <translation>und %1 weitere</translation>
    </message>
    <message>
        <source>Keeping %1&apos;s tool setter</source>
        <translation>Das Speichern des Werkzeugtasters von %1</translation>
    </message>
    <message>
        <source>Reading %1&apos;s tool setter</source>
        <translation>Das Lesen des Werkzeugtasters von %1</translation>
    </message>
    <message>
        <source>%1&apos;s tool setter in the library (&quot;%2&quot;) does not read: %3 Set it again (Machine ▸ Tool Setter…).</source>
        <translation>Der Werkzeugtaster von %1 in der Bibliothek („%2“) lässt sich nicht lesen: %3 Legen Sie ihn erneut fest (Maschine ▸ Werkzeugtaster …).</translation>
    </message>
    <message>
        <source>Nothing of this batch was recorded.</source>
        <translation>Nichts aus diesem Stapel wurde aufgezeichnet.</translation>
    </message>
    <message>
        <source>%1 is a library of version %2, read-only here, and too old to be read as it is. Open it once where it can be written (Toffee brings it up to date), or copy it.</source>
        <translation>%1 ist eine Bibliothek der Version %2, hier schreibgeschützt und zu alt, um so gelesen zu werden. Öffnen Sie sie einmal dort, wo sie geschrieben werden kann (Toffee bringt sie auf den neuesten Stand), oder kopieren Sie sie.</translation>
    </message>
    <message>
        <source>Reading which machine %1 is</source>
        <translation>Lesen, welche Maschine %1 ist</translation>
    </message>
    <message>
        <source>Keeping which machine %1 is</source>
        <translation>Speichern, welche Maschine %1 ist</translation>
    </message>
    <message>
        <source>A setter&apos;s repeatability takes 2 to %1 touches, each a machine position, and a time.</source>
        <translation>Die Wiederholgenauigkeit eines Längenmessgeräts braucht 2 bis %1 Antastungen, jede eine Maschinenposition, und eine Zeit.</translation>
    </message>
    <message>
        <source>Keeping %1&apos;s setter repeatability</source>
        <translation>Die Wiederholgenauigkeit des Längenmessgeräts von %1 speichern</translation>
    </message>
    <message>
        <source>%1&apos;s setter repeatability in the library does not read; measure it again (toffee-cli measure-repeatability).</source>
        <translation>Die Wiederholgenauigkeit des Längenmessgeräts von %1 in der Bibliothek ist nicht lesbar; messen Sie sie erneut (toffee-cli measure-repeatability).</translation>
    </message>
</context>
<context>
    <name>Toffee::LibraryLocation</name>
    <message>
        <source>%1 is not a valid PostgreSQL URL (%2). Write it as postgresql://user@host:port/dbname.</source>
        <translation>%1 ist keine gültige PostgreSQL-URL (%2). Schreiben Sie sie als postgresql://user@host:port/dbname.</translation>
    </message>
    <message>
        <source>%1 holds a password. Toffee never stores one: take it out of the URL and put it in the PostgreSQL password file (~/.pgpass, or the file PGPASSFILE names).</source>
        <translation>%1 enthält ein Passwort. Toffee speichert nie eines: Nehmen Sie es aus der URL heraus und tragen Sie es in die PostgreSQL-Passwortdatei ein (~/.pgpass oder die Datei, die PGPASSFILE nennt).</translation>
    </message>
    <message>
        <source>%1 names no database: write it after the host, as in postgresql://toffee@server/tools.</source>
        <translation>%1 nennt keine Datenbank: Schreiben Sie sie nach dem Host, wie in postgresql://toffee@server/tools.</translation>
    </message>
    <message>
        <source>%1: the database is named by one path part, as in postgresql://host/dbname.</source>
        <translation>%1: Die Datenbank wird mit genau einem Pfadteil benannt, wie in postgresql://host/dbname.</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a connection setting Toffee passes on (it takes %3).</source>
        <translation>%1: „%2“ ist keine Verbindungseinstellung, die Toffee weitergibt (es nimmt %3).</translation>
    </message>
    <message>
        <source>%1: the port must be between 1 and 65535.</source>
        <translation>%1: Der Port muss zwischen 1 und 65535 liegen.</translation>
    </message>
    <message>
        <source>No library was given: name an SQLite file, such as sqlite:library.sqlite, or a PostgreSQL database, such as postgresql://toffee@server/tools.</source>
        <translation>Es wurde keine Bibliothek angegeben: Nennen Sie eine SQLite-Datei, etwa sqlite:library.sqlite, oder eine PostgreSQL-Datenbank, etwa postgresql://toffee@server/tools.</translation>
    </message>
    <message>
        <source>%1: Toffee reads a library from an SQLite file (a path, or sqlite:PATH) or from PostgreSQL (postgresql://…), not from &quot;%2&quot;.</source>
        <translation>%1: Toffee liest eine Bibliothek aus einer SQLite-Datei (einem Pfad oder sqlite:PFAD) oder aus PostgreSQL (postgresql://…), nicht aus „%2“.</translation>
    </message>
    <message>
        <source>database %1 on %2</source>
        <translation>Datenbank %1 auf %2</translation>
    </message>
    <message>
        <source>the local server</source>
        <translation>dem lokalen Server</translation>
    </message>
</context>
<context>
    <name>Toffee::LibraryStatusLabel</name>
    <message>
        <source>Library status</source>
        <translation>Bibliotheksstatus</translation>
    </message>
    <message>
        <source>Library offline — 1 change waiting</source>
        <translation>Bibliothek offline — 1 Änderung wartet</translation>
    </message>
    <message>
        <source>Library offline — %1 changes waiting</source>
        <translation>Bibliothek offline — %1 Änderungen warten</translation>
    </message>
    <message>
        <source>Library cannot be written — 1 change waiting</source>
        <translation>Bibliothek nicht beschreibbar — 1 Änderung wartet</translation>
    </message>
    <message>
        <source>Library cannot be written — %1 changes waiting</source>
        <translation>Bibliothek nicht beschreibbar — %1 Änderungen warten</translation>
    </message>
    <message>
        <source>Library: %1 (read-only)</source>
        <translation>Bibliothek: %1 (schreibgeschützt)</translation>
    </message>
    <message>
        <source>Library: %1</source>
        <translation>Bibliothek: %1</translation>
    </message>
    <message>
        <source>Library back: nothing was waiting</source>
        <translation>Bibliothek wieder da: Nichts hat gewartet</translation>
    </message>
    <message>
        <source>Library back: 1 change written</source>
        <translation>Bibliothek wieder da: 1 Änderung geschrieben</translation>
    </message>
    <message>
        <source>Library back: %1 changes written</source>
        <translation>Bibliothek wieder da: %1 Änderungen geschrieben</translation>
    </message>
    <message>
        <source>Library read-only — 1 change kept on this station</source>
        <translation>Bibliothek schreibgeschützt — 1 Änderung auf dieser Station aufbewahrt</translation>
    </message>
    <message>
        <source>Library read-only — %1 changes kept on this station</source>
        <translation>Bibliothek schreibgeschützt — %1 Änderungen auf dieser Station aufbewahrt</translation>
    </message>
</context>
<context>
    <name>Toffee::LineReader</name>
    <message>
        <source>line %1 holds a NUL byte: this is not a text program (UTF-16, or not text at all?). Save it as plain text (UTF-8 or ASCII).</source>
        <translation>Zeile %1 enthält ein NUL-Byte: Das ist kein Textprogramm (UTF-16 oder gar kein Text?). Speichern Sie es als reinen Text (UTF-8 oder ASCII).</translation>
    </message>
    <message>
        <source>line %1 is longer than %2 KB; no program line is.</source>
        <translation>Zeile %1 ist länger als %2 KB; so lang ist keine Programmzeile.</translation>
    </message>
</context>
<context>
    <name>Toffee::LinuxCncAccessDialog</name>
    <message>
        <source>LinuxCNC Access for %1</source>
        <translation>LinuxCNC-Zugang für %1</translation>
    </message>
    <message>
        <source>found by itself when LinuxCNC runs on this computer</source>
        <translation>wird selbst gefunden, wenn LinuxCNC auf diesem Computer läuft</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s default (EMCTOO)</source>
        <translation>Voreinstellung von LinuxCNC (EMCTOO)</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>&amp;Durchsuchen…</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s INI</source>
        <translation>INI-Datei von LinuxCNC</translation>
    </message>
    <message>
        <source>LinuxCNC configurations (*.ini);;All files (*)</source>
        <translation>LinuxCNC-Konfigurationen (*.ini);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>linuxcncrsh cannot read LinuxCNC&apos;s tool table, so Toffee reads the file its INI names ([EMCIO] TOOL_TABLE) for push, pull and the job check. Its enable password lets Toffee take control (linuxcncrsh --enablepw); it is kept on this computer and never shown or logged.</source>
        <translation>linuxcncrsh kann die Werkzeugtabelle von LinuxCNC nicht lesen; Toffee liest deshalb für Übertragen, Abholen und die Programmprüfung die Datei, die die INI nennt ([EMCIO] TOOL_TABLE). Mit dem Freigabepasswort übernimmt Toffee die Steuerung (linuxcncrsh --enablepw); es bleibt auf diesem Computer und wird nie angezeigt oder protokolliert.</translation>
    </message>
    <message>
        <source>&amp;INI file:</source>
        <translation>&amp;INI-Datei:</translation>
    </message>
    <message>
        <source>&amp;Enable password:</source>
        <translation>&amp;Freigabepasswort:</translation>
    </message>
</context>
<context>
    <name>Toffee::LinuxCncController</name>
    <message>
        <source>The line &quot;%1&quot; is too long for linuxcncrsh; nothing was sent.</source>
        <translation>Die Zeile „%1“ ist zu lang für linuxcncrsh; es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>Stopped: LinuxCNC aborted &quot;%1&quot; where the machine stood. Nothing was measured or written; check where the spindle is before you go on.</source>
        <translation>Gestoppt: LinuxCNC hat „%1“ dort abgebrochen, wo die Maschine stand. Es wurde nichts gemessen oder geschrieben; prüfen Sie, wo die Spindel steht, bevor Sie weitermachen.</translation>
    </message>
    <message>
        <source>LinuxCNC refused &quot;%1&quot; and did not say why (get error: OK). Check LinuxCNC&apos;s own screen.</source>
        <translation>LinuxCNC lehnte „%1“ ab und sagte nicht, warum (get error: OK). Sehen Sie auf dem Bildschirm von LinuxCNC selbst nach.</translation>
    </message>
    <message>
        <source>LinuxCNC refused &quot;%1&quot;: %2</source>
        <translation>LinuxCNC lehnte „%1“ ab: %2</translation>
    </message>
    <message>
        <source>linuxcncrsh answered &quot;get %1&quot; with something else (%2); is this LinuxCNC?</source>
        <translation>linuxcncrsh beantwortete „get %1“ mit etwas anderem (%2); ist das LinuxCNC?</translation>
    </message>
    <message>
        <source>linuxcncrsh refused Toffee&apos;s hello (HELLO NAK): it was started with a connect password of its own (--connectpw), which Toffee does not know. Start it with the default (EMC), then connect again.</source>
        <translation>linuxcncrsh lehnte das hello von Toffee ab (HELLO NAK): Es wurde mit einem eigenen Verbindungspasswort gestartet (--connectpw), das Toffee nicht kennt. Starten Sie es mit der Voreinstellung (EMC) und verbinden Sie erneut.</translation>
    </message>
    <message>
        <source>LinuxCNC refused the enable password in this machine&apos;s settings (linuxcncrsh --enablepw). Set the right one, then connect again. Nothing was sent.</source>
        <translation>LinuxCNC lehnte das Freigabepasswort aus den Einstellungen dieser Maschine ab (linuxcncrsh --enablepw). Stellen Sie das richtige ein und verbinden Sie erneut. Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>This LinuxCNC&apos;s machine units are %1 ([TRAJ] LINEAR_UNITS); Toffee reads and writes millimetres only. Nothing was sent.</source>
        <translation>Die Maschineneinheiten dieses LinuxCNC sind %1 ([TRAJ] LINEAR_UNITS); Toffee liest und schreibt nur Millimeter. Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>select a tool</source>
        <translation>das Werkzeug wählen</translation>
    </message>
    <message>
        <source>LinuxCNC was told T%1 is in the spindle but says T%2.</source>
        <translation>LinuxCNC wurde mitgeteilt, dass T%1 in der Spindel ist, meldet aber T%2.</translation>
    </message>
    <message>
        <source>T%1 may be asked for at LinuxCNC&apos;s own screen (its manual tool change)</source>
        <translation>T%1 wird womöglich am Bildschirm von LinuxCNC selbst angefordert (sein manueller Werkzeugwechsel)</translation>
    </message>
    <message>
        <source>LinuxCNC changes to a tool, not to an empty spindle: use Select Tool with T0.</source>
        <translation>LinuxCNC wechselt zu einem Werkzeug, nicht zu einer leeren Spindel: Verwenden Sie „Werkzeug wählen“ mit T0.</translation>
    </message>
    <message>
        <source>change tools</source>
        <translation>das Werkzeug wechseln</translation>
    </message>
    <message>
        <source>LinuxCNC ended the change to T%1 with T%2 in the spindle: nothing was measured.</source>
        <translation>LinuxCNC beendete den Wechsel zu T%1 mit T%2 in der Spindel: Es wurde nichts gemessen.</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s change was aborted (set abort): check what is in the spindle, then select it and restore or probe its TLO before cutting.</source>
        <translation>Der Wechsel in LinuxCNC wurde abgebrochen (set abort): Prüfen Sie, was in der Spindel steckt, wählen Sie es dann und stellen Sie seine TLO wieder her oder messen Sie sie, bevor Sie zerspanen.</translation>
    </message>
    <message>
        <source>Toffee cannot %1 now: </source>
        <translation>Toffee kann jetzt nicht %1: </translation>
    </message>
    <message>
        <source>Nothing was sent.</source>
        <translation>Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>LinuxCNC is in estop. Release it at the machine (in AXIS: F1), then try again; Toffee never releases an estop itself.</source>
        <translation>LinuxCNC ist im Not-Aus (estop). Lösen Sie ihn an der Maschine (in AXIS: F1) und versuchen Sie es erneut; Toffee löst einen Not-Aus nie selbst.</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s machine is off. Switch it on (in AXIS: F2), then try again.</source>
        <translation>Die Maschine von LinuxCNC ist aus. Schalten Sie sie ein (in AXIS: F2) und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>LinuxCNC is not homed. Home every axis (in AXIS: Ctrl-Home), then try again.</source>
        <translation>LinuxCNC ist nicht referenziert. Referenzieren Sie alle Achsen (in AXIS: Ctrl-Home) und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>LinuxCNC is running a program or a line (%1). Wait until it is idle, then try again.</source>
        <translation>LinuxCNC führt ein Programm oder eine Zeile aus (%1). Warten Sie, bis es im Leerlauf ist, und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>LinuxCNC is in %1 mode; Toffee works through MDI and does not switch modes itself (a switch aborts whatever runs). Switch it to MDI (in AXIS: F5), then try again.</source>
        <translation>LinuxCNC ist im Modus %1; Toffee arbeitet über MDI und wechselt den Modus nicht selbst (ein Wechsel bricht ab, was gerade läuft). Schalten Sie auf MDI um (in AXIS: F5) und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>Another program took control of LinuxCNC (linuxcncrsh&apos;s enable) since Toffee connected. Make sure nobody else is driving it, then connect again.</source>
        <translation>Seit Toffee verbunden ist, hat ein anderes Programm die Kontrolle über LinuxCNC übernommen (das enable von linuxcncrsh). Stellen Sie sicher, dass niemand sonst sie bedient, und verbinden Sie erneut.</translation>
    </message>
    <message>
        <source>LinuxCNC is in inches (G20), where G10 and G38.2 take inches. Toffee works in millimetres: send G21, then try again.</source>
        <translation>LinuxCNC ist auf Zoll eingestellt (G20), sodass G10 und G38.2 Zoll erwarten. Toffee arbeitet in Millimetern: Senden Sie G21 und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>LinuxCNC did not print what Toffee asked of it (%1); it said &quot;%2&quot;. Nothing was recorded.</source>
        <translation>LinuxCNC hat nicht ausgegeben, was Toffee abgefragt hat (%1); es meldete „%2“. Es wurde nichts aufgezeichnet.</translation>
    </message>
    <message>
        <source>Cannot read LinuxCNC&apos;s INI %1: %2</source>
        <translation>Die INI-Datei %1 von LinuxCNC kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>linuxcncrsh cannot read LinuxCNC&apos;s tool table, so Toffee reads its file: give the INI LinuxCNC runs (toffee-cli --ini FILE) on the computer LinuxCNC runs on.</source>
        <translation>linuxcncrsh kann die Werkzeugtabelle von LinuxCNC nicht lesen, deshalb liest Toffee deren Datei: Geben Sie die INI an, mit der LinuxCNC läuft (toffee-cli --ini FILE), auf dem Computer, auf dem LinuxCNC läuft.</translation>
    </message>
    <message>
        <source>Cannot read LinuxCNC&apos;s tool table %1: %2</source>
        <translation>Die Werkzeugtabelle %1 von LinuxCNC kann nicht gelesen werden: %2</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s tool table %1 could not be read: %2</source>
        <translation>Die Werkzeugtabelle %1 von LinuxCNC ließ sich nicht lesen: %2</translation>
    </message>
    <message>
        <source>LinuxCNC says no tool is in the spindle (T0), so there is nothing to %1. Say which tool is in (Select Tool, M61 Q&lt;n&gt;) first.</source>
        <translation>LinuxCNC meldet kein Werkzeug in der Spindel (T0), daher lässt sich nichts %1. Geben Sie zuerst an, welches Werkzeug eingesetzt ist („Werkzeug wählen“, M61 Q&lt;n&gt;).</translation>
    </message>
    <message>
        <source>Toffee does not know where this machine&apos;s tool setter is. Set it first (Machine ▸ Tool Setter…, or toffee-cli --setter X,Y,ZMIN in machine coordinates).</source>
        <translation>Toffee weiß nicht, wo der Werkzeugtaster dieser Maschine ist. Legen Sie ihn zuerst fest (Maschine ▸ Werkzeugtaster …, oder toffee-cli --setter X,Y,ZMIN in Maschinenkoordinaten).</translation>
    </message>
    <message>
        <source>probe</source>
        <translation>antasten</translation>
    </message>
    <message>
        <source>measure</source>
        <translation>vermessen</translation>
    </message>
    <message>
        <source>break-test</source>
        <translation>auf Bruch prüfen</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO</source>
        <translation>Die TLO von T%1</translation>
    </message>
    <message>
        <source>Nothing was written to LinuxCNC or recorded.</source>
        <translation>Es wurde nichts in LinuxCNC geschrieben oder aufgezeichnet.</translation>
    </message>
    <message>
        <source>the offset in force reads %1 mm</source>
        <translation>der wirksame Versatz lautet %1 mm</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <source>%1 holds %2 for T%3</source>
        <translation>%1 enthält %2 für T%3</translation>
    </message>
    <message>
        <source>LinuxCNC was given T%1&apos;s TLO %2 mm, but read back %3. Nothing was recorded; check LinuxCNC&apos;s tool table before you cut.</source>
        <translation>LinuxCNC erhielt die TLO %2 mm für T%1, zurückgelesen wurde aber: %3. Es wurde nichts aufgezeichnet; prüfen Sie die Werkzeugtabelle von LinuxCNC, bevor Sie zerspanen.</translation>
    </message>
    <message>
        <source>The TLO</source>
        <translation>Die TLO</translation>
    </message>
    <message>
        <source>set a TLO for</source>
        <translation>mit einer TLO versehen</translation>
    </message>
    <message>
        <source>set a TLO</source>
        <translation>die TLO setzen</translation>
    </message>
    <message>
        <source>The height above Z0</source>
        <translation>Die Höhe über Z0</translation>
    </message>
    <message>
        <source>A TLO is restored for a tool, not for an empty spindle.</source>
        <translation>Eine TLO wird für ein Werkzeug wiederhergestellt, nicht für eine leere Spindel.</translation>
    </message>
    <message>
        <source>restore a TLO</source>
        <translation>die TLO wiederherstellen</translation>
    </message>
    <message>
        <source>%1 (the TLO that puts the tip %2 mm above Z0, from where it is)</source>
        <translation>%1 (die TLO, die die Spitze von ihrer jetzigen Position aus %2 mm über Z0 setzt)</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s tool table (%1) has no %2: G10 L1 cannot add a tool. Nothing was written: add them to LinuxCNC&apos;s table, or leave them out.</source>
        <translation>Die Werkzeugtabelle von LinuxCNC (%1) enthält %2 nicht: G10 L1 kann kein Werkzeug hinzufügen. Es wurde nichts geschrieben: Fügen Sie sie der Tabelle von LinuxCNC hinzu oder lassen Sie sie weg.</translation>
    </message>
    <message>
        <source>write LinuxCNC&apos;s table</source>
        <translation>die Tabelle von LinuxCNC schreiben</translation>
    </message>
    <message>
        <source>T%1 reads %2, not %3 mm</source>
        <translation>T%1 lautet %2, nicht %3 mm</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s table does not read back as written: %1. %2</source>
        <translation>Die Tabelle von LinuxCNC stimmt beim Zurücklesen nicht mit dem Geschriebenen überein: %1. %2</translation>
    </message>
    <message>
        <source>The probe was already touching, or touched something, before it probed (the setter&apos;s input triggered on the way to it or where it started): check the setter, its cable and the safe height. Nothing was measured. (%1)</source>
        <translation>Der Taster berührte schon oder stieß an etwas, bevor er antastete (der Eingang des Werkzeugtasters löste auf dem Weg dorthin oder am Start aus): Prüfen Sie den Werkzeugtaster, sein Kabel und die sichere Höhe. Es wurde nichts gemessen. (%1)</translation>
    </message>
    <message>
        <source>The probe was already touching at machine Z %1 mm, before it moved: the setter&apos;s input is triggered there. Check the setter, its cable and the safe height. Nothing was measured.</source>
        <translation>Der Taster berührte schon bei Maschinen-Z %1 mm, bevor er sich bewegte: Der Eingang des Werkzeugtasters ist dort ausgelöst. Prüfen Sie den Werkzeugtaster, sein Kabel und die sichere Höhe. Es wurde nichts gemessen.</translation>
    </message>
    <message>
        <source>The probe met nothing down to machine Z %1 mm: is a tool in the spindle, and is the setter where its settings say? Nothing was measured.</source>
        <translation>Der Taster traf bis Maschinen-Z %1 mm auf nichts: Steckt ein Werkzeug in der Spindel, und steht der Werkzeugtaster dort, wo seine Einstellungen sagen? Es wurde nichts gemessen.</translation>
    </message>
    <message>
        <source>LinuxCNC reported the contact at machine Z %1 mm, outside the move from %2 to %3 mm. Nothing was written or recorded; check the tool setter&apos;s settings and the machine.</source>
        <translation>LinuxCNC meldete die Berührung bei Maschinen-Z %1 mm, außerhalb der Bewegung von %2 bis %3 mm. Es wurde nichts geschrieben oder aufgezeichnet; prüfen Sie die Einstellungen des Werkzeugtasters und die Maschine.</translation>
    </message>
    <message>
        <source>T%1 cannot be probed so: %2 Nothing was sent.</source>
        <translation>T%1 kann so nicht angetastet werden: %2 Es wurde nichts gesendet.</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineConnection</name>
    <message>
        <source>Reading the offsets…</source>
        <translation>Korrekturen werden gelesen …</translation>
    </message>
    <message>
        <source>the current tool</source>
        <translation>das aktuelle Werkzeug</translation>
    </message>
    <message>
        <source>Probing %1…</source>
        <translation>Vermesse %1 …</translation>
    </message>
    <message>
        <source>Break-testing %1…</source>
        <translation>Bruchtest für %1 …</translation>
    </message>
    <message>
        <source>Setting %1&apos;s TLO…</source>
        <translation>TLO von %1 wird gesetzt …</translation>
    </message>
    <message>
        <source>Restoring T%1…</source>
        <translation>Stelle T%1 wieder her …</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>Entsperren</translation>
    </message>
    <message>
        <source>Reading the status…</source>
        <translation>Status wird gelesen…</translation>
    </message>
    <message>
        <source>Selecting T%1…</source>
        <translation>T%1 wird gewählt…</translation>
    </message>
    <message>
        <source>Changing to T%1…</source>
        <translation>Wechsel zu T%1…</translation>
    </message>
    <message>
        <source>Check the machine, then unlock it.</source>
        <translation>Prüfen Sie die Maschine und entsperren Sie sie dann.</translation>
    </message>
    <message>
        <source>The machine is halted (Alarm lock) and takes no command but Unlock. %1</source>
        <translation>Die Maschine ist angehalten (Alarm lock) und nimmt keinen Befehl außer Entsperren an. %1</translation>
    </message>
    <message>
        <source>Emptying the spindle…</source>
        <translation>Spindel wird geleert …</translation>
    </message>
    <message>
        <source>an unknown tool</source>
        <translation>ein unbekanntes Werkzeug</translation>
    </message>
    <message>
        <source>no tool</source>
        <translation>kein Werkzeug</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>Before &quot;%1&quot; the machine had %2 in the spindle with TLO %3; now it has %4 with TLO %5.</source>
        <translation>Vor „%1“ hatte die Maschine %2 in der Spindel mit Längenkorrektur %3; jetzt hat sie %4 mit Längenkorrektur %5.</translation>
    </message>
    <message>
        <source>Toffee cannot tell whether it ran. Nothing of it was recorded; check the machine and run it again.</source>
        <translation>Toffee kann nicht erkennen, ob es ausgeführt wurde. Nichts davon wurde aufgezeichnet; prüfen Sie die Maschine und führen Sie es erneut aus.</translation>
    </message>
    <message>
        <source>It ran on the machine, at least in part, but the machine&apos;s confirmation was lost: nothing of it was recorded. Run it again to record it.</source>
        <translation>Es lief auf der Maschine, zumindest teilweise, aber die Bestätigung der Maschine ging verloren: Nichts davon wurde aufgezeichnet. Führen Sie es erneut aus, um es aufzuzeichnen.</translation>
    </message>
    <message>
        <source>Nothing changed on the machine: it did not run, or it measured exactly the length held before. Nothing of it was recorded; run it again.</source>
        <translation>An der Maschine hat sich nichts geändert: Es lief nicht, oder es hat genau die vorherige Länge gemessen. Nichts davon wurde aufgezeichnet; führen Sie es erneut aus.</translation>
    </message>
    <message>
        <source>The machine holds no TLO now, as after a restart: Toffee cannot tell whether it ran. Nothing of it was recorded; check the tool in the spindle and measure it again.</source>
        <translation>Die Maschine hat jetzt keine Längenkorrektur, wie nach einem Neustart: Toffee kann nicht erkennen, ob es ausgeführt wurde. Nichts davon wurde aufgezeichnet; prüfen Sie das Werkzeug in der Spindel und messen Sie es erneut.</translation>
    </message>
    <message>
        <source>as asked.</source>
        <translation>wie gewünscht.</translation>
    </message>
    <message>
        <source>Reading the controller&apos;s tool table…</source>
        <translation>Werkzeugtabelle der Steuerung wird gelesen …</translation>
    </message>
    <message>
        <source>Writing the controller&apos;s tool table…</source>
        <translation>Werkzeugtabelle der Steuerung wird geschrieben …</translation>
    </message>
    <message>
        <source>%1 answered as %2, not as %3 as chosen. Nothing of %3&apos;s was sent. Choose %2, or Automatic (toffee-cli --controller %4, or auto), and connect again.</source>
        <translation>%1 hat als %2 geantwortet, nicht als %3 wie gewählt. Nichts %3-Spezifisches wurde gesendet. Wählen Sie %2 oder Automatisch (toffee-cli --controller %4 oder auto) und verbinden Sie erneut.</translation>
    </message>
    <message>
        <source>It said: &quot;%1&quot;. </source>
        <translation>Sie meldete: „%1“. </translation>
    </message>
    <message>
        <source>Jogging…</source>
        <translation>Tippbetrieb …</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineController</name>
    <message>
        <source>%1 keeps no tool table of its own: its tools&apos; TLOs are Toffee&apos;s table&apos;s alone.</source>
        <translation>%1 führt keine eigene Werkzeugtabelle: Die TLOs seiner Werkzeuge stehen allein in Toffees Tabelle.</translation>
    </message>
    <message>
        <source>The link to %1 did not open within %2 s. Check the machine and the connection, then try again.</source>
        <translation>Die Verbindung zu %1 wurde nicht innerhalb von %2 s geöffnet. Prüfen Sie die Maschine und die Verbindung und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>The break-test tolerance is not a number; enter a value such as 0.1 mm.</source>
        <translation>Die Toleranz des Bruchtests ist keine Zahl; geben Sie einen Wert wie 0,1 mm ein.</translation>
    </message>
    <message>
        <source>A break-test tolerance of %1 mm is too small: the machine halts below %2 mm. Use %2 mm or more (%3 mm is the default).</source>
        <translation>Eine Bruchtest-Toleranz von %1 mm ist zu klein: Unter %2 mm hält die Maschine an. Verwenden Sie %2 mm oder mehr (Standard: %3 mm).</translation>
    </message>
    <message>
        <source>A break-test tolerance of %1 mm is larger than any tool.</source>
        <translation>Eine Bruchtest-Toleranz von %1 mm ist größer als jedes Werkzeug.</translation>
    </message>
    <message>
        <source>%1 must be a number from -%2 to %2 mm.</source>
        <translation>%1 muss eine Zahl von -%2 bis %2 mm sein.</translation>
    </message>
    <message>
        <source>Tool %1 is not a tool number; use %2 to %3 (%4 for an empty spindle).</source>
        <translation>Werkzeug %1 ist keine Werkzeugnummer; verwenden Sie %2 bis %3 (%4 für eine leere Spindel).</translation>
    </message>
    <message>
        <source>A tool change is already under way.</source>
        <translation>Ein Werkzeugwechsel läuft bereits.</translation>
    </message>
    <message>
        <source>%1 on this machine: someone must be there to do it, but %2. Nothing was sent. Change the tool where someone can answer, or put it in by hand and select it.</source>
        <translation>%1 an dieser Maschine: Jemand muss dafür da sein, aber %2. Nichts wurde gesendet. Wechseln Sie das Werkzeug dort, wo jemand antworten kann, oder setzen Sie es von Hand ein und wählen Sie es aus.</translation>
    </message>
    <message>
        <source>Nobody put T%1 in within the %2 s the change waits.</source>
        <translation>Niemand hat T%1 innerhalb der %2 s eingesetzt, die der Wechsel wartet.</translation>
    </message>
    <message>
        <source>The change to T%1 was ended: nothing was measured or recorded. %2</source>
        <translation>Der Wechsel zu T%1 wurde beendet: Nichts wurde gemessen oder aufgezeichnet. %2</translation>
    </message>
    <message>
        <source>The machine&apos;s reading makes T%1&apos;s TLO %2 mm, beyond any tool (%3 mm at most): nothing was recorded. Check the tool setter and the machine&apos;s reference, then probe again.</source>
        <translation>Nach dem Messwert der Maschine wäre die Längenkorrektur von T%1 %2 mm, jenseits jedes Werkzeugs (höchstens %3 mm): Nichts wurde aufgezeichnet. Prüfen Sie den Werkzeugtaster und die Referenz der Maschine und messen Sie dann erneut.</translation>
    </message>
    <message>
        <source>%1 keeps its tool setter itself: Toffee does not jog it. Use the machine&apos;s own controls.</source>
        <translation>%1 verwaltet seinen Werkzeugtaster selbst: Toffee verfährt sie nicht im Tippbetrieb. Verwenden Sie die Bedienelemente der Maschine.</translation>
    </message>
    <message>
        <source>halt %1</source>
        <translation>Halt %1</translation>
    </message>
    <message>
        <source>The machine halted (reason %1).</source>
        <translation>Die Maschine hat angehalten (Grund %1).</translation>
    </message>
    <message>
        <source>Check the machine, then Unlock ($X).</source>
        <translation>Prüfen Sie die Maschine, dann Entsperren ($X).</translation>
    </message>
    <message>
        <source>T%1 measured %2 mm against its stored TLO %3 mm: %4 mm apart, more than the tolerance %5 mm. It may be broken or worn. The spindle is stopped and lifted; its stored TLO is kept in the table and in %6. Look at the tool and replace it before you cut.</source>
        <translation>T%1 ergab %2 mm gegenüber seinem gespeicherten TLO %3 mm: %4 mm Abstand, mehr als die Toleranz %5 mm. Es ist womöglich gebrochen oder verschlissen. Die Spindel ist gestoppt und angehoben; sein gespeicherter TLO bleibt in der Tabelle und in %6. Sehen Sie sich das Werkzeug an und ersetzen Sie es, bevor Sie schneiden.</translation>
    </message>
    <message>
        <source>Written before it: %1; not written: %2.</source>
        <translation>Davor geschrieben: %1; nicht geschrieben: %2.</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <source>This machine has no reference tool yet, so a new length cannot be compared. Probe a tool first: the first one measured becomes the reference.</source>
        <translation>Diese Maschine hat noch kein Referenzwerkzeug, daher lässt sich keine neue Länge vergleichen. Vermessen Sie zuerst ein Werkzeug: Das erste gemessene wird zur Referenz.</translation>
    </message>
    <message>
        <source>T%1 has no stored TLO to compare with, in the table or in %2&apos;s own: probe it first.</source>
        <translation>T%1 hat keine gespeicherte TLO zum Vergleich, weder in der Tabelle noch in der von %2: Messen Sie es zuerst.</translation>
    </message>
    <message>
        <source>T%1&apos;s edges differ by %2 mm (its limit %3 mm): runout or a chipped edge. Look at the cutter and how it sits in its holder before it cuts.</source>
        <translation>Die Schneiden von T%1 liegen %2 mm auseinander (Grenze %3 mm): Rundlauffehler oder eine ausgebrochene Schneide. Prüfen Sie den Fräser und seinen Sitz im Halter, bevor er schneidet.</translation>
    </message>
    <message>
        <source>T%1 is this machine&apos;s reference tool (its TLO is 0): every tool is measured against its contact at machine Z %2 mm.</source>
        <translation>T%1 ist das Referenzwerkzeug dieser Maschine (seine TLO ist 0): Jedes Werkzeug wird gegen dessen Kontakt bei Maschinen-Z %2 mm gemessen.</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineDock</name>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>Vermessen</translation>
    </message>
    <message>
        <source>Set the offset by hand</source>
        <translation>Korrektur von Hand setzen</translation>
    </message>
    <message>
        <source>Tool break test</source>
        <translation>Werkzeugbruchtest</translation>
    </message>
    <message>
        <source>What the machine&apos;s firmware cannot do</source>
        <translation>Was die Firmware der Maschine nicht kann</translation>
    </message>
    <message>
        <source>%1: no break test (its M491.1 only re-measures) and no manual offset (it ignores M493.3).</source>
        <translation>%1: kein Bruchtest (ihr M491.1 misst nur neu) und keine manuelle Korrektur (sie ignoriert M493.3).</translation>
    </message>
    <message>
        <source>%1: no break test (Toffee cannot tell whether its M491.1 compares a tool with its TLO).</source>
        <translation>%1: kein Bruchtest (Toffee kann nicht erkennen, ob ihr M491.1 ein Werkzeug mit seiner TLO vergleicht).</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineIdentity</name>
    <message>
        <source>the built-in emulator</source>
        <translation>der eingebaute Emulator</translation>
    </message>
    <message>
        <source>grblHAL “%1”</source>
        <translation>grblHAL „%1“</translation>
    </message>
    <message>
        <source>grblHAL at %1</source>
        <translation>grblHAL an %1</translation>
    </message>
    <message>
        <source>the Carvera at %1</source>
        <translation>die Carvera an %1</translation>
    </message>
    <message>
        <source>the machine at %1</source>
        <translation>die Maschine an %1</translation>
    </message>
    <message>
        <source>LinuxCNC at %1</source>
        <translation>LinuxCNC unter %1</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineLink</name>
    <message>
        <source>The machine did not answer &quot;%1&quot; within %2 s. The link was closed, because a late answer could be taken for the next command&apos;s. Reconnect, and check the machine before you go on.%3</source>
        <translation>Die Maschine hat auf „%1“ nicht innerhalb von %2 s geantwortet. Die Verbindung wurde geschlossen, weil eine späte Antwort für die des nächsten Befehls gehalten werden könnte. Verbinden Sie erneut und prüfen Sie die Maschine, bevor Sie weitermachen.%3</translation>
    </message>
    <message>
        <source>Not connected to the machine; connect first.</source>
        <translation>Nicht mit der Maschine verbunden; zuerst verbinden.</translation>
    </message>
    <message>
        <source>The machine refused &quot;%1&quot;: %2</source>
        <translation>Die Maschine hat „%1“ abgelehnt: %2</translation>
    </message>
    <message>
        <source>the link was closed</source>
        <translation>die Verbindung wurde geschlossen</translation>
    </message>
    <message>
        <source>The connection to the machine was lost while it ran &quot;%1&quot;: %2</source>
        <translation>Die Verbindung zur Maschine ging verloren, während sie „%1“ ausführte: %2</translation>
    </message>
    <message>
        <source>The connection to the machine was lost: %1</source>
        <translation>Die Verbindung zur Maschine ging verloren: %1</translation>
    </message>
    <message>
        <source>The machine halted: %1</source>
        <translation>Die Maschine hat angehalten: %1</translation>
    </message>
    <message>
        <source>Meanwhile it printed %1 lines that were no answer; only the last %2 were kept. A machine that prints that much is not well: check its firmware and the cable.</source>
        <translation>Inzwischen hat sie %1 Zeilen ausgegeben, die keine Antwort waren; nur die letzten %2 wurden behalten. Eine Maschine, die so viel ausgibt, ist nicht in Ordnung: Prüfen Sie ihre Firmware und das Kabel.</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineSession</name>
    <message>
        <source>The machine printed %1 lines before its answer; only the last %2 were kept, and the result may have been among the others.</source>
        <translation>Die Maschine hat vor ihrer Antwort %1 Zeilen ausgegeben; nur die letzten %2 wurden behalten, und das Ergebnis war vielleicht unter den anderen.</translation>
    </message>
    <message>
        <source>M493.2 T%1, then M493.3 Z%2</source>
        <translation>M493.2 T%1, dann M493.3 Z%2</translation>
    </message>
    <message>
        <source>The machine sent no status report within 2 s, and the TLO in force is read from it. Nothing was recorded; check the cable or the Wi-Fi and try again.</source>
        <translation>Die Maschine hat innerhalb von 2 s keinen Statusbericht gesendet, und die wirksame Längenkorrektur wird daraus gelesen. Nichts wurde aufgezeichnet; prüfen Sie das Kabel oder das WLAN und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>The machine&apos;s offset report (M493.4) holds values no machine can have: &quot;%1&quot;. Nothing was recorded; check the offsets on the machine before you cut.</source>
        <translation>Der Korrekturbericht der Maschine (M493.4) enthält Werte, die keine Maschine haben kann: „%1“. Nichts wurde gespeichert; prüfen Sie die Korrekturen an der Maschine, bevor Sie schneiden.</translation>
    </message>
    <message>
        <source>The machine&apos;s offset report (M493.4) could not be read%1. Nothing was recorded; try again, and check the cable or the Wi-Fi if it happens twice.</source>
        <translation>Der Korrekturbericht der Maschine (M493.4) konnte nicht gelesen werden%1. Nichts wurde aufgezeichnet; versuchen Sie es erneut, und prüfen Sie das Kabel oder das WLAN, wenn es zweimal passiert.</translation>
    </message>
    <message>
        <source>The machine sent no status report within 2 s.</source>
        <translation>Die Maschine hat innerhalb von 2 s keinen Statusbericht gesendet.</translation>
    </message>
    <message>
        <source>The machine finished probing but its probe result ([PRB:…]) could not be read. Nothing was recorded; check the offsets (Report) before you cut.</source>
        <translation>Die Maschine hat die Messung beendet, aber das Messergebnis ([PRB:…]) war nicht lesbar. Nichts wurde gespeichert; prüfen Sie die Korrekturen (Bericht), bevor Sie schneiden.</translation>
    </message>
    <message>
        <source>The machine measured the tool, but its two reports disagree: the TLO in force is %1 mm, and its offset report does not add up to it. Nothing was recorded; probe again.</source>
        <translation>Die Maschine hat das Werkzeug vermessen, aber ihre beiden Berichte widersprechen sich: Die gültige Längenkorrektur ist %1 mm, und ihr Korrekturbericht ergibt sie nicht. Nichts wurde aufgezeichnet; vermessen Sie erneut.</translation>
    </message>
    <message>
        <source>The firmware&apos;s break test takes T%1 for its wireless probe (T0, and every tool from T9 up): it would measure the tool, then halt. Break-test tools T1 to T8, or probe T%1 and compare its TLO with the table.</source>
        <translation>Die Bruchprüfung der Firmware hält T%1 für ihren Funktaster (T0 und jedes Werkzeug ab T9): Sie würde das Werkzeug vermessen und dann anhalten. Prüfen Sie die Werkzeuge T1 bis T8 auf Bruch, oder vermessen Sie T%1 und vergleichen Sie seine Längenkorrektur mit der Tabelle.</translation>
    </message>
    <message>
        <source>The stored TLO</source>
        <translation>Die gespeicherte Längenkorrektur</translation>
    </message>
    <message>
        <source>The machine sent no status report within 2 s; no break test was run.</source>
        <translation>Die Maschine hat innerhalb von 2 s keinen Statusbericht gesendet; es wurde keine Bruchprüfung ausgeführt.</translation>
    </message>
    <message>
        <source>The machine compared T%1 with a TLO of %2 mm, not its stored %3 mm, so its verdict does not hold. Check the offsets, then run the break test again.</source>
        <translation>Die Maschine hat T%1 mit einer Längenkorrektur von %2 mm verglichen, nicht mit den gespeicherten %3 mm; ihr Ergebnis gilt daher nicht. Prüfen Sie die Korrekturen und führen Sie die Bruchprüfung erneut aus.</translation>
    </message>
    <message>
        <source>Tool T%1 may be broken: it measured a TLO of %2 mm against %3 mm before (a difference of %4 mm; the tolerance is %5 mm). The machine has halted with the new length, %2 mm, in force. Check the tool and replace it if it is damaged, then Unlock: Toffee sets the stored TLO, %3 mm, back first.</source>
        <translation>Werkzeug T%1 ist möglicherweise gebrochen: Es wurde mit einer Längenkorrektur von %2 mm gemessen, zuvor %3 mm (eine Differenz von %4 mm; die Toleranz ist %5 mm). Die Maschine hat angehalten, mit der neuen Länge %2 mm in Kraft. Prüfen Sie das Werkzeug und ersetzen Sie es, falls es beschädigt ist, dann Entsperren: Toffee setzt zuerst die gespeicherte Längenkorrektur %3 mm zurück.</translation>
    </message>
    <message>
        <source>The machine had no TLO for this tool to compare with: it measured the tool and took the new length without comparing. Check the TLO it reports against the table before you cut.</source>
        <translation>Die Maschine hatte für dieses Werkzeug keine Längenkorrektur zum Vergleich: Sie hat das Werkzeug vermessen und die neue Länge ohne Vergleich übernommen. Prüfen Sie die gemeldete Längenkorrektur anhand der Tabelle, bevor Sie schneiden.</translation>
    </message>
    <message>
        <source>The break test ran but its result (&quot;Old: … , new: …&quot;) could not be read. Run it again before you trust the tool.</source>
        <translation>Der Bruchtest ist gelaufen, aber sein Ergebnis („Old: … , new: …“) war nicht lesbar. Starten Sie ihn erneut, bevor Sie dem Werkzeug trauen.</translation>
    </message>
    <message>
        <source>Tool T%1 measured %2 mm against %3 mm, more than the %4 mm tolerance.</source>
        <translation>Werkzeug T%1 hat %2 mm gemessen, vorher %3 mm, mehr als die Toleranz von %4 mm.</translation>
    </message>
    <message>
        <source>The machine was told TLO %1 mm but reports %2 mm in force. Check the offsets before you cut.</source>
        <translation>Der Maschine wurde die Längenkorrektur %1 mm gesendet, sie meldet aber %2 mm in Kraft. Prüfen Sie die Korrekturen, bevor Sie schneiden.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keins</translation>
    </message>
    <message>
        <source>The tool length offset</source>
        <translation>Die Werkzeuglängenkorrektur</translation>
    </message>
    <message>
        <source>The height above Z0</source>
        <translation>Die Höhe über Z0</translation>
    </message>
    <message>
        <source>The machine sent no status report within 2 s; its TLO was not set.</source>
        <translation>Die Maschine hat innerhalb von 2 s keinen Statusbericht gesendet; ihre Längenkorrektur wurde nicht gesetzt.</translation>
    </message>
    <message>
        <source>The machine finished changing to T%1, but its probe result ([PRB:…]) could not be read. Nothing was recorded; probe the tool again.</source>
        <translation>Die Maschine hat zu T%1 gewechselt, aber ihr Tastergebnis ([PRB:…]) ließ sich nicht lesen. Nichts wurde aufgezeichnet; vermessen Sie das Werkzeug erneut.</translation>
    </message>
    <message>
        <source>The machine sent no status report within 2 s; it was not unlocked.</source>
        <translation>Die Maschine hat innerhalb von 2 s keinen Statusbericht gesendet; sie wurde nicht entsperrt.</translation>
    </message>
    <message>
        <source>The machine was not halted.</source>
        <translation>Die Maschine war nicht angehalten.</translation>
    </message>
    <message>
        <source>The machine did not confirm the unlock; check its state before you go on.</source>
        <translation>Die Maschine hat das Entsperren nicht bestätigt; prüfen Sie ihren Zustand, bevor Sie weitermachen.</translation>
    </message>
    <message>
        <source>Unlocked. T%1&apos;s stored TLO, %2 mm, is in force again (the break test had left the new length in force).</source>
        <translation>Entsperrt. Die gespeicherte Längenkorrektur von T%1, %2 mm, ist wieder in Kraft (die Bruchprüfung hatte die neue Länge in Kraft gelassen).</translation>
    </message>
    <message>
        <source>Unlocked, but the stored TLO (%1 mm) could not be set back: %2 The length the break test measured is still in force; do not cut.</source>
        <translation>Entsperrt, aber die gespeicherte Längenkorrektur (%1 mm) ließ sich nicht zurücksetzen: %2 Die bei der Bruchprüfung gemessene Länge ist noch in Kraft; schneiden Sie nicht.</translation>
    </message>
    <message>
        <source>The machine answered but sent no status report; is this a Carvera?</source>
        <translation>Die Maschine hat geantwortet, aber keinen Statusbericht gesendet; ist das eine Carvera?</translation>
    </message>
    <message>
        <source>The machine did not answer &quot;%1&quot; within the %2 s allowed for connecting. Check that it is on, and the cable or the Wi-Fi, then connect again (or allow longer).</source>
        <translation>Die Maschine hat „%1“ nicht innerhalb der %2 s beantwortet, die für das Verbinden vorgesehen sind. Prüfen Sie, ob sie eingeschaltet ist, und das Kabel oder das WLAN, und verbinden Sie sich erneut (oder lassen Sie mehr Zeit).</translation>
    </message>
    <message>
        <source>The machine did not finish connecting within the %1 s allowed: it answered too slowly, or not at all. Check that it is on, and the cable or the Wi-Fi, then connect again (or allow longer).</source>
        <translation>Die Maschine hat das Verbinden nicht innerhalb der vorgesehenen %1 s abgeschlossen: Sie antwortete zu langsam oder gar nicht. Prüfen Sie, ob sie eingeschaltet ist, und das Kabel oder das WLAN, und verbinden Sie sich erneut (oder lassen Sie mehr Zeit).</translation>
    </message>
    <message>
        <source>The machine stayed busy (%1) for the %2 s allowed for connecting. Wait for it to finish, or stop it, then connect again.</source>
        <translation>Die Maschine blieb während der %2 s, die zum Verbinden erlaubt sind, beschäftigt (%1). Warten Sie, bis sie fertig ist, oder halten Sie sie an, und verbinden Sie dann erneut.</translation>
    </message>
    <message>
        <source>The machine was told to put its tool back, but it reports T%1 in the spindle. Check the spindle and the rack before you go on.</source>
        <translation>Die Maschine sollte ihr Werkzeug zurücklegen, meldet aber T%1 in der Spindel. Prüfen Sie Spindel und Magazin, bevor Sie fortfahren.</translation>
    </message>
    <message>
        <source>The machine was told to put its tool back but did not report an empty spindle. Check the spindle and the rack before you go on.</source>
        <translation>Die Maschine sollte ihr Werkzeug zurücklegen, hat aber keine leere Spindel gemeldet. Prüfen Sie Spindel und Magazin, bevor Sie fortfahren.</translation>
    </message>
    <message>
        <source>The machine runs %1: its M491.1 only measures the tool again and takes the new length without comparing, so a broken tool would pass. Probe the tool and compare its TLO with the table, or install the community firmware for break tests.</source>
        <translation>Auf der Maschine läuft %1: Ihr M491.1 vermisst das Werkzeug nur erneut und übernimmt die neue Länge ohne Vergleich, ein gebrochenes Werkzeug würde also bestehen. Vermessen Sie das Werkzeug und vergleichen Sie seine TLO mit der Tabelle, oder installieren Sie die Community-Firmware für Bruchtests.</translation>
    </message>
    <message>
        <source>The machine did not say which firmware it runs (%1), so Toffee cannot tell whether its M491.1 compares the tool or only measures it again. No break test was run; probe the tool and compare its TLO with the table.</source>
        <translation>Die Maschine hat nicht angegeben, welche Firmware sie verwendet (%1), daher kann Toffee nicht erkennen, ob ihr M491.1 das Werkzeug vergleicht oder nur erneut vermisst. Es wurde kein Bruchtest ausgeführt; vermessen Sie das Werkzeug und vergleichen Sie seine TLO mit der Tabelle.</translation>
    </message>
    <message>
        <source>The machine runs %1, which ignores M493.3 without a word: a TLO set by hand would not be used. Probe the tool instead, or change to it with its TLO (a manual change).</source>
        <translation>Auf der Maschine läuft %1, die M493.3 stillschweigend ignoriert: Eine von Hand gesetzte TLO würde nicht verwendet. Vermessen Sie stattdessen das Werkzeug, oder wechseln Sie mit seiner TLO zu ihm (ein manueller Wechsel).</translation>
    </message>
    <message>
        <source>the tool in the spindle, which this firmware does not name, may be taken out by hand</source>
        <translation>das Werkzeug in der Spindel, das diese Firmware nicht nennt, wird womöglich von Hand entnommen</translation>
    </message>
    <message>
        <source>T%1 is taken out by hand</source>
        <translation>T%1 wird von Hand entnommen</translation>
    </message>
    <message>
        <source>%1 and T%2 put in by hand</source>
        <translation>%1 und T%2 von Hand eingesetzt</translation>
    </message>
    <message>
        <source>T%1 is put in by hand</source>
        <translation>T%1 wird von Hand eingesetzt</translation>
    </message>
    <message>
        <source>The machine halted to end it: check what is in the spindle, unlock it, then select the tool and probe it before cutting.</source>
        <translation>Die Maschine hat angehalten, um ihn zu beenden: Prüfen Sie, was in der Spindel steckt, entsperren Sie sie, wählen Sie dann das Werkzeug aus und messen Sie es, bevor Sie schneiden.</translation>
    </message>
    <message>
        <source>%1, which no Carvera does: this is another controller (grblHAL refuses it so). Nothing of the Carvera&apos;s was sent. Choose grblHAL, or Automatic, and connect again.</source>
        <translation>%1, was keine Carvera tut: Das ist eine andere Steuerung (grblHAL lehnt es so ab). Nichts Carvera-Spezifisches wurde gesendet. Wählen Sie grblHAL oder Automatisch und verbinden Sie erneut.</translation>
    </message>
    <message>
        <source>The machine says the spindle is empty (T-1): a TLO set now would be kept by the firmware and given to whichever tool is selected next. Put the tool in and select it (Machine ▸ Select Tool, toffee-cli select-tool N), then set its TLO. Nothing was sent.</source>
        <translation>Die Maschine meldet eine leere Spindel (T-1): Eine jetzt gesetzte TL würde die Firmware behalten und dem nächsten gewählten Werkzeug geben. Setzen Sie das Werkzeug ein und wählen Sie es (Maschine ▸ Werkzeug wählen, toffee-cli select-tool N), dann setzen Sie seine TL. Nichts wurde gesendet.</translation>
    </message>
    <message>
        <source>Unlocked. The TLO in force is %1 mm, as the machine left it: after a failed break test, the length the test measured. No stored TLO of T%2 was known here to set back (toffee-cli: --table FILE, or the history that recorded the test). Probe T%2, or set its TLO, before it cuts.</source>
        <translation>Entsperrt. Die wirksame TL ist %1 mm, wie die Maschine sie ließ: nach einem fehlgeschlagenen Bruchtest die vom Test gemessene Länge. Keine gespeicherte TL von T%2 war hier bekannt, um sie zurückzusetzen (toffee-cli: --table DATEI oder der Verlauf, der den Test aufzeichnete). Vermessen Sie T%2 oder setzen Sie seine TL, bevor es schneidet.</translation>
    </message>
    <message>
        <source>Makera&apos;s firmware measures a tool once, at the setter&apos;s centre (its M491 takes no R, X or Y): T%1&apos;s settings (%2) need the community firmware. Nothing was sent.</source>
        <translation>Die Firmware von Makera misst ein Werkzeug einmal, in der Mitte des Längenmessgeräts (ihr M491 kennt kein R, X oder Y): Die Einstellungen von T%1 (%2) brauchen die Community-Firmware. Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>T%1 cannot be probed so: %2 Nothing was sent.</source>
        <translation>T%1 kann so nicht angetastet werden: %2 Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>Between its %1 touches the firmware lifts 25 mm for you to turn the cutter to its next edge by hand.</source>
        <translation>Zwischen den %1 Antastungen hebt die Firmware um 25 mm an, damit Sie den Fräser von Hand zur nächsten Schneide drehen.</translation>
    </message>
    <message>
        <source>The firmware touches at its own latch feed (atc.probe.slow_rate_mm_m in its config), not T%1&apos;s %2 mm/min.</source>
        <translation>Die Firmware tastet mit ihrem eigenen Feinvorschub an (atc.probe.slow_rate_mm_m in ihrer Konfiguration), nicht mit den %2 mm/min von T%1.</translation>
    </message>
    <message>
        <source>The firmware printed %1 of the %2 measurements it was asked for (M491 R%2). Nothing was recorded; check the offsets (Report) before you cut.</source>
        <translation>Die Firmware gab %1 der %2 verlangten Messungen aus (M491 R%2). Es wurde nichts aufgezeichnet; prüfen Sie die Offsets (Bericht), bevor Sie schneiden.</translation>
    </message>
    <message>
        <source>The firmware reported no reference tool offset, so its %1 measurements cannot be put in machine coordinates. Nothing was recorded.</source>
        <translation>Die Firmware meldete keinen Referenzwerkzeug-Offset, daher können ihre %1 Messungen nicht in Maschinenkoordinaten umgerechnet werden. Es wurde nichts aufgezeichnet.</translation>
    </message>
    <message>
        <source>Toffee set the longest edge&apos;s TLO (%2 mm) where the firmware kept the shortest&apos;s (%1 mm): no edge cuts deeper than the offset says.</source>
        <translation>Toffee hat die TLO der längsten Schneide (%2 mm) gesetzt, wo die Firmware die der kürzesten (%1 mm) behielt: Keine Schneide schneidet tiefer, als der Offset sagt.</translation>
    </message>
    <message>
        <source>The firmware&apos;s break test (M491.1) touches at the setter&apos;s centre only, and T%1 is measured off-centre: probe it (M491 with its settings) and compare the TLO with the table instead. Nothing was sent.</source>
        <translation>Der Bruchtest der Firmware (M491.1) tastet nur in der Mitte des Längenmessgeräts an, und T%1 wird außermittig gemessen: Tasten Sie es stattdessen an (M491 mit seinen Einstellungen) und vergleichen Sie die TLO mit der Tabelle. Es wurde nichts gesendet.</translation>
    </message>
    <message>
        <source>The firmware&apos;s break test touched T%1 once, at one edge, not the %2 touches its settings ask for: probe it to compare every edge.</source>
        <translation>Der Bruchtest der Firmware hat T%1 einmal angetastet, an einer Schneide, nicht %2-mal, wie seine Einstellungen verlangen: Tasten Sie es an, um jede Schneide zu vergleichen.</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineTableDialog</name>
    <message>
        <source>Open a machine&apos;s table</source>
        <translation>Die Tabelle einer Maschine öffnen</translation>
    </message>
    <message>
        <source>Open Machine Table</source>
        <translation>Maschinentabelle öffnen</translation>
    </message>
    <message>
        <source>Machine tables in %1:</source>
        <translation>Maschinentabellen in %1:</translation>
    </message>
    <message>
        <source>Library</source>
        <translation>Bibliothek</translation>
    </message>
    <message>
        <source>Machines</source>
        <translation>Maschinen</translation>
    </message>
    <message>
        <source>Open or cancel</source>
        <translation>Öffnen oder abbrechen</translation>
    </message>
    <message>
        <source>Open the machine&apos;s table</source>
        <translation>Die Tabelle der Maschine öffnen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>Toffee::MainWindow</name>
    <message>
        <source>Tool tables (*.json *.tbl *.csv);;Toffee tool table (*.json);;LinuxCNC tool table (*.tbl);;CSV spreadsheet (*.csv);;All files (*)</source>
        <translation>Werkzeugtabellen (*.json *.tbl *.csv);;Toffee-Werkzeugtabelle (*.json);;LinuxCNC-Werkzeugtabelle (*.tbl);;CSV-Tabelle (*.csv);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Cannot connect to the machine</source>
        <translation>Keine Verbindung zur Maschine möglich</translation>
    </message>
    <message>
        <source>Disconnected: %1</source>
        <translation>Getrennt: %1</translation>
    </message>
    <message>
        <source>1 tool</source>
        <translation>1 Werkzeug</translation>
    </message>
    <message>
        <source>%1 tools</source>
        <translation>%1 Werkzeuge</translation>
    </message>
    <message>
        <source>Value not accepted</source>
        <translation>Wert nicht übernommen</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>Haupt</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>&amp;Neu</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Öffnen …</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>&amp;Speichern</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Speichern &amp;unter …</translation>
    </message>
    <message>
        <source>Import &amp;Tools…</source>
        <translation>&amp;Werkzeuge importieren …</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>&amp;Exportieren …</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Rückgängig</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Wiederholen</translation>
    </message>
    <message>
        <source>&amp;Add Tool</source>
        <translation>Werkzeug &amp;hinzufügen</translation>
    </message>
    <message>
        <source>&amp;Remove Tool</source>
        <translation>Werkzeug &amp;entfernen</translation>
    </message>
    <message>
        <source>&amp;Filter…</source>
        <translation>&amp;Filtern …</translation>
    </message>
    <message>
        <source>%1 was changed by another program.

Reload it? Your unsaved changes in Toffee would be lost.</source>
        <translation>%1 wurde von einem anderen Programm geändert.

Neu laden? Ihre ungespeicherten Änderungen in Toffee gingen verloren.</translation>
    </message>
    <message>
        <source>%1 was changed by another program.

Reload it?</source>
        <translation>%1 wurde von einem anderen Programm geändert.

Neu laden?</translation>
    </message>
    <message>
        <source>File changed on disk</source>
        <translation>Datei auf der Festplatte geändert</translation>
    </message>
    <message>
        <source>Cannot reload the tool table</source>
        <translation>Die Werkzeugtabelle lässt sich nicht neu laden</translation>
    </message>
    <message>
        <source>The table on screen has not been changed.</source>
        <translation>Die angezeigte Tabelle wurde nicht verändert.</translation>
    </message>
    <message>
        <source>Reloaded %1</source>
        <translation>%1 neu geladen</translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation>&amp;Maschine</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>Maschine</translation>
    </message>
    <message>
        <source>&amp;Connect / Disconnect</source>
        <translation>&amp;Verbinden / Trennen</translation>
    </message>
    <message>
        <source>&amp;Probe Current Tool…</source>
        <translation>Aktuelles Werkzeug &amp;vermessen …</translation>
    </message>
    <message>
        <source>&amp;Break Test…</source>
        <translation>&amp;Bruchtest …</translation>
    </message>
    <message>
        <source>&amp;Unlock</source>
        <translation>&amp;Entsperren</translation>
    </message>
    <message>
        <source>&amp;Stop the Machine</source>
        <translation>Maschine &amp;anhalten</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Dark Palette</source>
        <translation>&amp;Dunkle Farben</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>Verbinde mit %1 …</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>Unbenannt</translation>
    </message>
    <message>
        <source>Cannot open the tool table</source>
        <translation>Die Werkzeugtabelle lässt sich nicht öffnen</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>%1 geöffnet</translation>
    </message>
    <message>
        <source>Open Tool Table</source>
        <translation>Werkzeugtabelle öffnen</translation>
    </message>
    <message>
        <source>Save as %1?</source>
        <translation>Als %1 speichern?</translation>
    </message>
    <message>
        <source>Cannot save the tool table</source>
        <translation>Die Werkzeugtabelle lässt sich nicht speichern</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>%1 gespeichert</translation>
    </message>
    <message>
        <source>Save Tool Table</source>
        <translation>Werkzeugtabelle speichern</translation>
    </message>
    <message>
        <source>Import Tools</source>
        <translation>Werkzeuge importieren</translation>
    </message>
    <message>
        <source>Cannot import</source>
        <translation>Import nicht möglich</translation>
    </message>
    <message>
        <source>Nothing was imported.</source>
        <translation>Nichts wurde importiert.</translation>
    </message>
    <message>
        <source>Imported %1 tools from %2</source>
        <translation>%1 Werkzeuge aus %2 importiert</translation>
    </message>
    <message>
        <source>Export Tool Table</source>
        <translation>Werkzeugtabelle exportieren</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation>Export nicht möglich</translation>
    </message>
    <message>
        <source>Exported to %1</source>
        <translation>Nach %1 exportiert</translation>
    </message>
    <message>
        <source>Cannot add a tool</source>
        <translation>Werkzeug lässt sich nicht hinzufügen</translation>
    </message>
    <message>
        <source>Every tool number is in use.</source>
        <translation>Alle Werkzeugnummern sind vergeben.</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The tool table has changes that are not saved.
Save them first?</source>
        <translation>Die Werkzeugtabelle hat ungespeicherte Änderungen.
Zuerst speichern?</translation>
    </message>
    <message>
        <source>The machine is busy</source>
        <translation>Die Maschine ist beschäftigt</translation>
    </message>
    <message>
        <source>The machine is running &quot;%1&quot;. Stop it and quit?</source>
        <translation>Die Maschine führt „%1“ aus. Anhalten und beenden?</translation>
    </message>
    <message>
        <source>Export for &amp;Controller…</source>
        <translation>Für &amp;Steuerung exportieren …</translation>
    </message>
    <message>
        <source>Recover Unsaved Edits</source>
        <translation>Ungesicherte Änderungen wiederherstellen</translation>
    </message>
    <message>
        <source>Toffee stopped before a new table was saved. Its last copy is from %1.</source>
        <translation>Toffee wurde beendet, bevor eine neue Tabelle gespeichert war. Ihre letzte Kopie ist von %1.</translation>
    </message>
    <message>
        <source>Toffee stopped before the edits to %1 were saved. Their last copy is from %2.</source>
        <translation>Toffee wurde beendet, bevor die Änderungen an %1 gespeichert waren. Ihre letzte Kopie ist von %2.</translation>
    </message>
    <message>
        <source>The copy holds %1 tools. Recover puts it on top of the file as it is on disk, unsaved: review it, then save; Undo shows the file as it was. Discard deletes the copy; Later keeps it for the next start.</source>
        <translation>Die Kopie enthält %1 Werkzeuge. „Wiederherstellen“ legt sie ungespeichert über die Datei, wie sie auf der Festplatte liegt: prüfen, dann speichern; „Rückgängig“ zeigt die Datei, wie sie war. „Verwerfen“ löscht die Kopie; „Später“ hebt sie für den nächsten Start auf.</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>&amp;Wiederherstellen</translation>
    </message>
    <message>
        <source>&amp;Later</source>
        <translation>&amp;Später</translation>
    </message>
    <message>
        <source>Unsaved edits are not protected against a crash until they are saved: %1</source>
        <translation>Ungesicherte Änderungen sind bis zum Speichern nicht gegen einen Absturz geschützt: %1</translation>
    </message>
    <message>
        <source>Recovered unsaved edits: review them, then save.</source>
        <translation>Ungesicherte Änderungen wiederhergestellt: prüfen, dann speichern.</translation>
    </message>
    <message>
        <source>Some copies of unsaved edits could not be read (%1 in all), so they cannot be recovered.</source>
        <translation>Einige Kopien ungesicherter Änderungen waren nicht lesbar (insgesamt %1); sie lassen sich nicht wiederherstellen.</translation>
    </message>
    <message>
        <source>Copies moved to %2, never to be offered again: %1.</source>
        <translation>Nach %2 verschoben und nie wieder angeboten: %1.</translation>
    </message>
    <message>
        <source>Copies that could not be moved to %2 and were left, untouched, in %3 (look at them there, or remove them by hand): %1.</source>
        <translation>Nicht nach %2 verschiebbar und daher unverändert in %3 belassen (dort ansehen oder von Hand entfernen): %1.</translation>
    </message>
    <message>
        <source>Nothing else was changed.</source>
        <translation>Sonst wurde nichts verändert.</translation>
    </message>
    <message>
        <source>Machine State</source>
        <translation>Maschinenzustand</translation>
    </message>
    <message>
        <source>T%1 shares pocket %2 with %3. LinuxCNC&apos;s random tool changer needs each tool in its own pocket.</source>
        <translation>T%1 teilt sich Platz %2 mit %3. Der zufällige Werkzeugwechsler (random tool changer) von LinuxCNC braucht für jedes Werkzeug einen eigenen Platz.</translation>
    </message>
    <message>
        <source>halted</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <source>After saving, the table on screen shows what the file holds; until the window is closed, Undo brings the rest back. To keep everything, Cancel and use Save As with a .json file.

Save anyway?</source>
        <translation>Nach dem Speichern zeigt die Tabelle auf dem Bildschirm, was die Datei enthält; bis das Fenster geschlossen wird, holt Rückgängig den Rest zurück. Um alles zu behalten, brechen Sie ab und verwenden Sie „Speichern unter“ mit einer .json-Datei.

Trotzdem speichern?</translation>
    </message>
    <message>
        <source>The history library cannot be written: %1 Measurements wait here and are written as soon as it can be.</source>
        <translation>Die Verlaufsbibliothek lässt sich nicht schreiben: %1 Die Messungen warten hier und werden geschrieben, sobald es geht.</translation>
    </message>
    <message>
        <source>The history library is written again: every waiting measurement is in it.</source>
        <translation>Die Verlaufsbibliothek wird wieder geschrieben: Jede wartende Messung ist darin.</translation>
    </message>
    <message>
        <source>Export History</source>
        <translation>Verlauf exportieren</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>The history was not exported</source>
        <translation>Der Verlauf wurde nicht exportiert</translation>
    </message>
    <message>
        <source>Exported %1 measurements to %2</source>
        <translation>%1 Messungen nach %2 exportiert</translation>
    </message>
    <message>
        <source>&amp;Record a Program Run…</source>
        <translation>&amp;Programmlauf aufzeichnen…</translation>
    </message>
    <message>
        <source>Record a Program Run</source>
        <translation>Programmlauf aufzeichnen</translation>
    </message>
    <message>
        <source>G-code programs (*.nc *.gcode *.ngc *.tap *.cnc);;All files (*)</source>
        <translation>G-Code-Programme (*.nc *.gcode *.ngc *.tap *.cnc);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>The program run was not recorded</source>
        <translation>Der Programmlauf wurde nicht aufgezeichnet</translation>
    </message>
    <message>
        <source>Recorded the cutting time of %1 tools from %2.</source>
        <translation>Die Schnittzeit von %1 Werkzeugen aus %2 wurde aufgezeichnet.</translation>
    </message>
    <message>
        <source>History &amp;Library…</source>
        <translation>&amp;Verlaufsbibliothek…</translation>
    </message>
    <message>
        <source>Tool tables and CAM libraries (*.json *.tbl *.csv *.tools *.hsmlib *.nc *.gcode *.cnc *.ngc *.tap *.txt);;Toffee tool table (*.json);;LinuxCNC tool table (*.tbl);;CSV spreadsheet (*.csv);;Fusion tool library (*.json *.tools);;HSM tool library (*.hsmlib);;Makera CAM program (*.nc *.gcode *.cnc *.ngc *.tap *.txt);;All files (*)</source>
        <translation>Werkzeugtabellen und CAM-Bibliotheken (*.json *.tbl *.csv *.tools *.hsmlib *.nc *.gcode *.cnc *.ngc *.tap *.txt);;Toffee-Werkzeugtabelle (*.json);;LinuxCNC-Werkzeugtabelle (*.tbl);;CSV-Tabelle (*.csv);;Fusion-Werkzeugbibliothek (*.json *.tools);;HSM-Werkzeugbibliothek (*.hsmlib);;Makera-CAM-Programm (*.nc *.gcode *.cnc *.ngc *.tap *.txt);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Import tools from %1</source>
        <translation>Werkzeuge aus %1 importieren</translation>
    </message>
    <message>
        <source>Imported from %1: %2</source>
        <translation>Importiert aus %1: %2</translation>
    </message>
    <message>
        <source>Check &amp;Job…</source>
        <translation>&amp;Job prüfen …</translation>
    </message>
    <message>
        <source>Check Job</source>
        <translation>Job prüfen</translation>
    </message>
    <message>
        <source>G-code programs (*.nc *.gcode *.ngc *.tap *.cnc *.gc *.g *.pgm *.mpf);;All files (*)</source>
        <translation>G-Code-Programme (*.nc *.gcode *.ngc *.tap *.cnc *.gc *.g *.pgm *.mpf);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Rack</source>
        <translation>Magazin</translation>
    </message>
    <message>
        <source>The shared library cannot be used</source>
        <translation>Die gemeinsame Bibliothek lässt sich nicht verwenden</translation>
    </message>
    <message>
        <source>Open &amp;Machine Table…</source>
        <translation>&amp;Maschinentabelle öffnen …</translation>
    </message>
    <message>
        <source>Save to &amp;Library…</source>
        <translation>&amp;In Bibliothek speichern …</translation>
    </message>
    <message>
        <source>Open Machine Table</source>
        <translation>Maschinentabelle öffnen</translation>
    </message>
    <message>
        <source>The library (%1) is not open, so its machine tables cannot be listed: %2</source>
        <translation>Die Bibliothek (%1) ist nicht geöffnet, daher lassen sich ihre Maschinentabellen nicht auflisten: %2</translation>
    </message>
    <message>
        <source>The library (%1) holds no machine tables yet. File ▸ Save to Library… puts the open table there as a machine&apos;s table.</source>
        <translation>Die Bibliothek (%1) enthält noch keine Maschinentabellen. Datei ▸ In Bibliothek speichern … legt die geöffnete Tabelle dort als Tabelle einer Maschine ab.</translation>
    </message>
    <message>
        <source>The library (%1) is not open: %2</source>
        <translation>Die Bibliothek (%1) ist nicht geöffnet: %2</translation>
    </message>
    <message>
        <source>Cannot open the machine&apos;s table</source>
        <translation>Die Tabelle der Maschine lässt sich nicht öffnen</translation>
    </message>
    <message>
        <source>Opened %1&apos;s table from %2</source>
        <translation>Tabelle von %1 aus %2 geöffnet</translation>
    </message>
    <message>
        <source>Cannot save to the library</source>
        <translation>Speichern in der Bibliothek nicht möglich</translation>
    </message>
    <message>
        <source>The machine&apos;s name in the library</source>
        <translation>Der Name der Maschine in der Bibliothek</translation>
    </message>
    <message>
        <source>Save to Library</source>
        <translation>In Bibliothek speichern</translation>
    </message>
    <message>
        <source>Save this table in %1 as the table of the machine:</source>
        <translation>Diese Tabelle in %1 als Tabelle der Maschine speichern:</translation>
    </message>
    <message>
        <source>Nothing was written to the library.</source>
        <translation>In die Bibliothek wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Saved as %1&apos;s table in %2</source>
        <translation>Als Tabelle von %1 in %2 gespeichert</translation>
    </message>
    <message>
        <source>This table came from %1, and the window now works with %2. Use Save As to keep it in a file, or choose %1 again in Machine ▸ History Library….</source>
        <translation>Diese Tabelle stammt aus %1, und das Fenster arbeitet jetzt mit %2. Verwenden Sie „Speichern unter“, um sie in einer Datei zu behalten, oder wählen Sie %1 wieder unter Maschine ▸ Verlaufsbibliothek….</translation>
    </message>
    <message>
        <source>Nothing was written: the table on screen keeps your changes.</source>
        <translation>Es wurde nichts geschrieben: Die Tabelle auf dem Bildschirm behält Ihre Änderungen.</translation>
    </message>
    <message>
        <source>The library cannot be reached: your changes are kept on this station and written when it is back.</source>
        <translation>Die Bibliothek ist nicht erreichbar: Ihre Änderungen werden auf dieser Station aufbewahrt und geschrieben, sobald sie wieder da ist.</translation>
    </message>
    <message>
        <source>Saved 1 tool to %1&apos;s table in %2</source>
        <translation>1 Werkzeug in der Tabelle von %1 in %2 gespeichert</translation>
    </message>
    <message>
        <source>Saved %1 tools to %2&apos;s table in %3</source>
        <translation>%1 Werkzeuge in der Tabelle von %2 in %3 gespeichert</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>%1 (read-only)</source>
        <translation>%1 (schreibgeschützt)</translation>
    </message>
    <message>
        <source>Read-only: your role may read this library but not change it. Whoever runs the server can give it write rights.</source>
        <translation>Schreibgeschützt: Ihre Rolle darf diese Bibliothek lesen, aber nicht ändern. Der Betreiber des Servers kann ihr Schreibrechte geben.</translation>
    </message>
    <message>
        <source>Read-only: the library file %1 cannot be written, so this table can be read but not changed.</source>
        <translation>Schreibgeschützt: Die Bibliotheksdatei %1 lässt sich nicht schreiben, daher kann diese Tabelle gelesen, aber nicht geändert werden.</translation>
    </message>
    <message>
        <source>another station</source>
        <translation>einer anderen Station</translation>
    </message>
    <message>
        <source>T%1 was changed on %2</source>
        <translation>T%1 wurde auf %2 geändert</translation>
    </message>
    <message>
        <source>your edit is kept — Save to choose.</source>
        <translation>Ihre Änderung bleibt erhalten — zum Auswählen speichern.</translation>
    </message>
    <message>
        <source>your edits are kept — Save to choose.</source>
        <translation>Ihre Änderungen bleiben erhalten — zum Auswählen speichern.</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>Nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>Changed on Another Station While the Library Was Offline</source>
        <translation>Auf einer anderen Station geändert, während die Bibliothek offline war</translation>
    </message>
    <message>
        <source>%1&apos;s table keeps the other station&apos;s tools.</source>
        <translation>Die Tabelle von %1 behält die Werkzeuge der anderen Station.</translation>
    </message>
    <message>
        <source>Toffee records into this station&apos;s own library (%1) until the shared one is fixed (Machine ▸ History Library…).</source>
        <translation>Toffee zeichnet in die eigene Bibliothek dieser Station (%1) auf, bis die gemeinsame in Ordnung gebracht ist (Maschine ▸ Verlaufsbibliothek…).</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About Toffee</source>
        <translation>Ü&amp;ber Toffee</translation>
    </message>
    <message>
        <source>Connected again</source>
        <translation>Wieder verbunden</translation>
    </message>
    <message>
        <source>The link to the machine was lost</source>
        <translation>Die Verbindung zur Maschine ist abgerissen</translation>
    </message>
    <message>
        <source>The link to the machine was lost during &quot;%1&quot;: %2</source>
        <translation>Die Verbindung zur Maschine ist während „%1“ abgerissen: %2</translation>
    </message>
    <message>
        <source>Nothing of it was written to the tool table or the history: the machine did not confirm it. Reconnect to read the machine&apos;s offsets back; Toffee then says whether it happened.</source>
        <translation>Nichts davon wurde in die Werkzeugtabelle oder den Verlauf geschrieben: Die Maschine hat es nicht bestätigt. Verbinden Sie sich erneut, um die Korrekturen der Maschine zurückzulesen; Toffee sagt dann, ob es geschehen ist.</translation>
    </message>
    <message>
        <source>Reconnect</source>
        <translation>Erneut verbinden</translation>
    </message>
    <message>
        <source>Not Now</source>
        <translation>Nicht jetzt</translation>
    </message>
    <message>
        <source>The link to the machine was lost: %1</source>
        <translation>Die Verbindung zur Maschine ist abgerissen: %1</translation>
    </message>
    <message>
        <source>Nothing was running. Reconnect to read the machine&apos;s tool and TLO again.</source>
        <translation>Es lief nichts. Verbinden Sie sich erneut, um Werkzeug und Längenkorrektur der Maschine wieder zu lesen.</translation>
    </message>
    <message>
        <source>Remove T%1?</source>
        <translation>T%1 entfernen?</translation>
    </message>
    <message>
        <source>Remove %1 tools?</source>
        <translation>%1 Werkzeuge entfernen?</translation>
    </message>
    <message>
        <source>%1 has a measured TLO, which goes with it from the table (the history keeps its measurements).</source>
        <translation>%1 hat eine gemessene Längenkorrektur, die mit ihm aus der Tabelle verschwindet (der Verlauf behält seine Messungen).</translation>
    </message>
    <message>
        <source>Edit ▸ Undo brings it back.</source>
        <translation>Bearbeiten ▸ Rückgängig holt es zurück.</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <source>R&amp;ack</source>
        <translation>Ma&amp;gazin</translation>
    </message>
    <message>
        <source>&amp;Measure Rack…</source>
        <translation>Magazin &amp;vermessen …</translation>
    </message>
    <message>
        <source>&amp;Check Rack…</source>
        <translation>Magazin &amp;prüfen …</translation>
    </message>
    <message>
        <source>Tool &amp;Setter…</source>
        <translation>&amp;Werkzeugtaster …</translation>
    </message>
    <message>
        <source>Push &amp;Offsets to the Controller…</source>
        <translation>&amp;Korrekturen an die Steuerung übertragen …</translation>
    </message>
    <message>
        <source>P&amp;ull Offsets from the Controller…</source>
        <translation>Korrekturen von der Steuerung über&amp;nehmen …</translation>
    </message>
    <message>
        <source>For a controller that keeps a tool table of its own (grblHAL): connect to one first.</source>
        <translation>Für eine Steuerung mit eigener Werkzeugtabelle (grblHAL): Verbinden Sie sich zuerst mit einer.</translation>
    </message>
    <message>
        <source>The tool setter is kept on this computer only: %1</source>
        <translation>Der Werkzeugtaster wird nur auf diesem Computer gespeichert: %1</translation>
    </message>
    <message>
        <source>%1&apos;s tool setter: X %2, Y %3, lowest Z %4 mm.</source>
        <translation>Werkzeugtaster von %1: X %2, Y %3, tiefstes Z %4 mm.</translation>
    </message>
    <message>
        <source>Cannot read the controller&apos;s tool table</source>
        <translation>Die Werkzeugtabelle der Steuerung lässt sich nicht lesen</translation>
    </message>
    <message>
        <source>beyond its table (T1 to T%1)</source>
        <translation>außerhalb ihrer Tabelle (T1 bis T%1)</translation>
    </message>
    <message>
        <source>unchanged</source>
        <translation>unverändert</translation>
    </message>
    <message>
        <source>written</source>
        <translation>geschrieben</translation>
    </message>
    <message>
        <source>The offsets were not all pushed</source>
        <translation>Nicht alle Korrekturen wurden übertragen</translation>
    </message>
    <message>
        <source>empty in the controller: left alone</source>
        <translation>in der Steuerung leer: unberührt gelassen</translation>
    </message>
    <message>
        <source>taken, as set on the controller</source>
        <translation>übernommen, wie in der Steuerung gesetzt</translation>
    </message>
    <message>
        <source>new tool</source>
        <translation>neues Werkzeug</translation>
    </message>
    <message>
        <source>Pull Offsets from %1</source>
        <translation>Korrekturen von %1 übernehmen</translation>
    </message>
    <message>
        <source>Taken from the controller&apos;s table into the file: %1 TLOs.</source>
        <translation>Aus der Tabelle der Steuerung in die Datei übernommen: %1 TLOs.</translation>
    </message>
    <message>
        <source>New &amp;Cutter…</source>
        <translation>Neuer &amp;Fräser…</translation>
    </message>
    <message>
        <source>Select the one tool whose cutter was changed.</source>
        <translation>Wählen Sie das eine Werkzeug, dessen Fräser gewechselt wurde.</translation>
    </message>
    <message>
        <source>its TLO %1 %2 (%3)</source>
        <translation>seine TLO %1 %2 (%3)</translation>
    </message>
    <message>
        <source>set by hand</source>
        <translation>von Hand gesetzt</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <source>its wear (length %1, radius %2)</source>
        <translation>sein Verschleiß (Länge %1, Radius %2)</translation>
    </message>
    <message>
        <source>its broken mark</source>
        <translation>seine Bruchmarkierung</translation>
    </message>
    <message>
        <source>its used life</source>
        <translation>seine verbrauchte Standzeit</translation>
    </message>
    <message>
        <source>New cutter in T%1?</source>
        <translation>Neuer Fräser in T%1?</translation>
    </message>
    <message>
        <source>T%1 gets a new cutter. Measure it on the tool setter before it cuts.</source>
        <translation>T%1 bekommt einen neuen Fräser. Vermessen Sie ihn vor dem Zerspanen am Werkzeugtaster.</translation>
    </message>
    <message>
        <source>T%1 gets a new cutter: %2 belong to the old one and end here (the history keeps them as the old cutter&apos;s). Measure T%1 on the tool setter before it cuts.</source>
        <translation>T%1 bekommt einen neuen Fräser: %2 gehören zum alten und enden hier (der Verlauf behält sie als die des alten Fräsers). Vermessen Sie T%1 vor dem Zerspanen am Werkzeugtaster.</translation>
    </message>
    <message>
        <source>New Cutter</source>
        <translation>Neuer Fräser</translation>
    </message>
    <message>
        <source>Cannot put in a new cutter</source>
        <translation>Neuer Fräser nicht möglich</translation>
    </message>
    <message>
        <source>T%1 has a new cutter: measure it before it cuts.</source>
        <translation>T%1 hat einen neuen Fräser: vor dem Zerspanen vermessen.</translation>
    </message>
    <message>
        <source>Which unit?</source>
        <translation>Welche Einheit?</translation>
    </message>
    <message>
        <source>Millimetres</source>
        <translation>Millimeter</translation>
    </message>
    <message>
        <source>Inches</source>
        <translation>Zoll</translation>
    </message>
    <message>
        <source>This table is read-only here, so a measurement could not be kept in it. Open a table you may change to probe, set or test tools.</source>
        <translation>Diese Tabelle ist hier schreibgeschützt, eine Messung ließe sich darin nicht behalten. Öffnen Sie eine Tabelle, die Sie ändern dürfen, um Werkzeuge zu vermessen, zu setzen oder zu prüfen.</translation>
    </message>
    <message>
        <source>Edit ▸ Undo puts the old values back in the table; the history keeps that a new cutter went in, and the job check warns of a TLO from before it.</source>
        <translation>Bearbeiten ▸ Rückgängig setzt die alten Werte wieder in die Tabelle; der Verlauf behält, dass ein neuer Fräser eingesetzt wurde, und die Auftragsprüfung warnt vor einer TLO von davor.</translation>
    </message>
    <message>
        <source>Tools in %2 without a unit (Fusion writes &quot;unit&quot; on every tool): %1. Their diameters and lengths are read in the unit you choose; the preview shows each of them before anything changes.</source>
        <translation>Werkzeuge in %2 ohne Einheit (Fusion schreibt „unit“ an jedes Werkzeug): %1. Ihre Durchmesser und Längen werden in der gewählten Einheit gelesen; die Vorschau zeigt jedes davon, bevor sich etwas ändert.</translation>
    </message>
    <message>
        <source>The offsets were not pulled</source>
        <translation>Die Korrekturen wurden nicht übernommen</translation>
    </message>
    <message>
        <source>“%1” is %2, new to the history library.</source>
        <translation>„%1“ ist %2, neu in der Verlaufsbibliothek.</translation>
    </message>
    <message>
        <source>Another machine under this name</source>
        <translation>Eine andere Maschine unter diesem Namen</translation>
    </message>
    <message>
        <source>“%1” in the history library is %2; this is %3.</source>
        <translation>„%1“ ist in der Verlaufsbibliothek %2; dies ist %3.</translation>
    </message>
    <message>
        <source>A machine&apos;s reference, tool setter and history are its own. If this is the same machine reached another way, say so; if not, give it a name of its own (Machine ▸ History Library…, Machine name) and connect again.</source>
        <translation>Referenz, Werkzeugsensor und Verlauf gehören jeweils zu einer Maschine. Wenn dies dieselbe Maschine auf anderem Weg ist, sagen Sie es; wenn nicht, geben Sie ihr einen eigenen Namen (Maschine ▸ Verlaufsbibliothek…, Maschinenname) und verbinden Sie erneut.</translation>
    </message>
    <message>
        <source>Same Machine</source>
        <translation>Dieselbe Maschine</translation>
    </message>
    <message>
        <source>Not connected: “%1” in the history library is %2, not %3. Give this machine a name of its own (Machine ▸ History Library…, Machine name), then connect again.</source>
        <translation>Nicht verbunden: „%1“ ist in der Verlaufsbibliothek %2, nicht %3. Geben Sie dieser Maschine einen eigenen Namen (Maschine ▸ Verlaufsbibliothek…, Maschinenname) und verbinden Sie dann erneut.</translation>
    </message>
    <message>
        <source>“%1” was %2 before; now it is %3.</source>
        <translation>„%1“ war vorher %2; jetzt ist es %3.</translation>
    </message>
    <message>
        <source>The selected tool&apos;s pocket holds another cutter: its TLO, length, wear and break mark end, and it is measured before it cuts</source>
        <translation>Der Platz des gewählten Werkzeugs hält einen anderen Fräser: TLO, Länge, Verschleiß und Bruchmarke enden, und er wird vor dem Schneiden vermessen</translation>
    </message>
    <message>
        <source>its length %1 %2</source>
        <translation>seine Länge %1 %2</translation>
    </message>
    <message>
        <source>read from the controller</source>
        <translation>aus der Steuerung gelesen</translation>
    </message>
    <message>
        <source>User&apos;s &amp;Guide</source>
        <translation>Benutzer&amp;handbuch</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>The System&apos;s</source>
        <translation>Die des Systems</translation>
    </message>
    <message>
        <source>The window speaks %1 from its next start.</source>
        <translation>Das Fenster spricht ab dem nächsten Start %1.</translation>
    </message>
    <message>
        <source>the system&apos;s language</source>
        <translation>die Sprache des Systems</translation>
    </message>
    <message>
        <source>not in its table</source>
        <translation>nicht in seiner Tabelle</translation>
    </message>
    <message>
        <source>%1 cannot go into %2&apos;s table of %3 tools: nothing is pushed. Renumber them, or remove their TLOs, and push again.</source>
        <translation>%1 passen nicht in die Tabelle von %2 mit %3 Werkzeugen: Es wird nichts übertragen. Nummerieren Sie sie um oder entfernen Sie ihre TLOs und übertragen Sie erneut.</translation>
    </message>
    <message>
        <source>%1 are not in %2&apos;s tool table, and G10 L1 cannot add a tool: nothing is pushed. Add them to its table, or remove their TLOs, and push again.</source>
        <translation>%1 stehen nicht in der Werkzeugtabelle von %2, und G10 L1 kann kein Werkzeug hinzufügen: Es wird nichts übertragen. Fügen Sie sie seiner Tabelle hinzu oder entfernen Sie ihre TLOs und übertragen Sie erneut.</translation>
    </message>
    <message>
        <source>Written into %1&apos;s table and read back, all agreeing: %2 TLOs.</source>
        <translation>In die Tabelle von %1 geschrieben und zurückgelesen, alle stimmen überein: %2 TLOs.</translation>
    </message>
    <message>
        <source>&amp;LinuxCNC Access…</source>
        <translation>&amp;LinuxCNC-Zugang…</translation>
    </message>
    <message>
        <source>this machine</source>
        <translation>diese Maschine</translation>
    </message>
    <message>
        <source>The LinuxCNC access is kept on this computer; it applies from the next connection.</source>
        <translation>Der LinuxCNC-Zugang bleibt auf diesem Computer; er gilt ab der nächsten Verbindung.</translation>
    </message>
</context>
<context>
    <name>Toffee::OffsetEditor</name>
    <message>
        <source>Send</source>
        <translation>Senden</translation>
    </message>
    <message>
        <source>How to set the offset</source>
        <translation>Wie die Korrektur gesetzt wird</translation>
    </message>
    <message>
        <source>Set TLO to</source>
        <translation>TLO setzen auf</translation>
    </message>
    <message>
        <source>Change TLO by</source>
        <translation>TLO ändern um</translation>
    </message>
    <message>
        <source>Gauge height above Z0</source>
        <translation>Lehrenhöhe über Z0</translation>
    </message>
    <message>
        <source>Offset value in millimetres</source>
        <translation>Korrekturwert in Millimetern</translation>
    </message>
    <message>
        <source>Command that will be sent</source>
        <translation>Befehl, der gesendet wird</translation>
    </message>
    <message>
        <source>Resulting tool length offset</source>
        <translation>Resultierende Werkzeuglängenkorrektur</translation>
    </message>
    <message>
        <source>Send the offset to the machine</source>
        <translation>Korrektur an die Maschine senden</translation>
    </message>
    <message>
        <source>Send the command above — Ctrl+Enter</source>
        <translation>Den Befehl oben senden — Strg+Enter</translation>
    </message>
    <message>
        <source>Sends:</source>
        <translation>Sendet:</translation>
    </message>
    <message>
        <source>TLO:</source>
        <translation>TLO:</translation>
    </message>
    <message>
        <source>(the current TLO is not known yet)</source>
        <translation>(die aktuelle Längenkorrektur ist noch nicht bekannt)</translation>
    </message>
    <message>
        <source>%1 → set by the machine from the spindle&apos;s position</source>
        <translation>%1 → von der Maschine aus der Spindelposition gesetzt</translation>
    </message>
    <message>
        <source>The offset was not set</source>
        <translation>Die Korrektur wurde nicht gesetzt</translation>
    </message>
    <message>
        <source>Change %1&apos;s tool length offset?</source>
        <translation>Werkzeuglängenkorrektur von %1 ändern?</translation>
    </message>
    <message>
        <source>Send %1 for %2?
TLO %3

The next cut uses the new offset. The table records it as set by hand, not measured.</source>
        <translation>%1 für %2 senden?
TLO %3

Der nächste Schnitt verwendet die neue Korrektur. Die Tabelle speichert sie als von Hand gesetzt, nicht gemessen.</translation>
    </message>
    <message>
        <source>Nothing was written to the tool table.</source>
        <translation>In die Werkzeugtabelle wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>the machine reports no tool in the spindle.</source>
        <translation>Die Maschine meldet kein Werkzeug in der Spindel.</translation>
    </message>
    <message>
        <source>The offset is set but not recorded</source>
        <translation>Die Korrektur ist gesetzt, aber nicht gespeichert</translation>
    </message>
    <message>
        <source>The machine now has TLO %1, but the table could not record it: %2</source>
        <translation>Die Maschine hat jetzt TLO %1, aber die Tabelle konnte sie nicht speichern: %2</translation>
    </message>
</context>
<context>
    <name>Toffee::OffsetSyncDialog</name>
    <message>
        <source>Push Offsets to %1</source>
        <translation>Korrekturen an %1 übertragen</translation>
    </message>
    <message>
        <source>Pull Offsets from %1</source>
        <translation>Korrekturen von %1 übernehmen</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>TLO in the file</source>
        <translation>TLO in der Datei</translation>
    </message>
    <message>
        <source>TLO in %1</source>
        <translation>TLO in %1</translation>
    </message>
    <message>
        <source>Pushing</source>
        <translation>Übertragung</translation>
    </message>
    <message>
        <source>Pulling</source>
        <translation>Übernahme</translation>
    </message>
    <message>
        <source>Nothing to change: the file and %1 agree.</source>
        <translation>Nichts zu ändern: Die Datei und %1 stimmen überein.</translation>
    </message>
    <message>
        <source>The TLOs in bold (%1) will be written into %2&apos;s own table and read back. The file does not change.</source>
        <translation>Die fett gedruckten TLOs (%1) werden in die eigene Tabelle von %2 geschrieben und zurückgelesen. Die Datei ändert sich nicht.</translation>
    </message>
    <message>
        <source>The TLOs in bold (%1) will be taken into the file as set on %2, not measured by Toffee, each with a history event. %2 does not change.</source>
        <translation>Die fett gedruckten TLOs (%1) werden so in die Datei übernommen, wie sie in %2 gesetzt sind, nicht von Toffee gemessen, jede mit einem Verlaufseintrag. %2 ändert sich nicht.</translation>
    </message>
    <message>
        <source>&amp;Push</source>
        <translation>Ü&amp;bertragen</translation>
    </message>
    <message>
        <source>P&amp;ull</source>
        <translation>Über&amp;nehmen</translation>
    </message>
</context>
<context>
    <name>Toffee::ProbePanel</name>
    <message>
        <source>Probe Current Tool</source>
        <translation>Aktuelles Werkzeug vermessen</translation>
    </message>
    <message>
        <source>Restore Known TLO</source>
        <translation>Bekannte TLO wiederherstellen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Probe the current tool on the tool setter</source>
        <translation>Das aktuelle Werkzeug am Werkzeugtaster vermessen</translation>
    </message>
    <message>
        <source>Measure the tool in the spindle on the tool setter (M491) — F5</source>
        <translation>Das Werkzeug in der Spindel am Werkzeugtaster messen (M491) — F5</translation>
    </message>
    <message>
        <source>Restore the selected tool&apos;s known TLO</source>
        <translation>Bekannte Längenkorrektur des gewählten Werkzeugs wiederherstellen</translation>
    </message>
    <message>
        <source>Make the selected tool active with the TLO measured before, without probing — Ctrl+R</source>
        <translation>Das gewählte Werkzeug mit der früher gemessenen Längenkorrektur aktivieren, ohne zu vermessen — Strg+R</translation>
    </message>
    <message>
        <source>Machine busy</source>
        <translation>Maschine beschäftigt</translation>
    </message>
    <message>
        <source>Stop the machine</source>
        <translation>Maschine anhalten</translation>
    </message>
    <message>
        <source>Stop the machine now (Ctrl-X to the controller) — Esc</source>
        <translation>Die Maschine sofort anhalten (Strg-X an die Steuerung) — Esc</translation>
    </message>
    <message>
        <source>Restore T%1 TLO</source>
        <translation>TLO von T%1 wiederherstellen</translation>
    </message>
    <message>
        <source>Nothing was written to the tool table.</source>
        <translation>In die Werkzeugtabelle wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>Probe %1?</source>
        <translation>%1 vermessen?</translation>
    </message>
    <message>
        <source>there is no tool in the spindle.</source>
        <translation>In der Spindel ist kein Werkzeug.</translation>
    </message>
    <message>
        <source>Probing failed</source>
        <translation>Vermessen fehlgeschlagen</translation>
    </message>
    <message>
        <source>Restore T%1?</source>
        <translation>T%1 wiederherstellen?</translation>
    </message>
    <message>
        <source>Restoring failed</source>
        <translation>Wiederherstellen fehlgeschlagen</translation>
    </message>
    <message>
        <source>T%1 measured: TLO %2, recorded in the table.</source>
        <translation>T%1 gemessen: TLO %2, in der Tabelle gespeichert.</translation>
    </message>
    <message>
        <source>Measured TLO %1, but it could not be recorded: %2</source>
        <translation>TLO %1 gemessen, aber sie konnte nicht gespeichert werden: %2</translation>
    </message>
    <message>
        <source>Is T%1 in the spindle now?</source>
        <translation>Ist T%1 jetzt in der Spindel?</translation>
    </message>
    <message>
        <source>The machine will use T%1&apos;s TLO %2 (%3, %4) without probing. If another tool is in the spindle, the next cut is off by the difference.</source>
        <translation>Die Maschine verwendet die TLO %2 von T%1 (%3, %4), ohne zu vermessen. Ist ein anderes Werkzeug in der Spindel, weicht der nächste Schnitt um die Differenz ab.</translation>
    </message>
    <message>
        <source>set by hand</source>
        <translation>von Hand gesetzt</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <source>T%1 failed its last break test.</source>
        <translation>T%1 hat seinen letzten Bruchtest nicht bestanden.</translation>
    </message>
    <message>
        <source>T%1 Is in the Spindle</source>
        <translation>T%1 ist in der Spindel</translation>
    </message>
    <message>
        <source>T%1 is active with TLO %2.</source>
        <translation>T%1 ist aktiv mit TLO %2.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO does not fit this machine&apos;s reference</source>
        <translation>Die TLO von T%1 passt nicht zur Referenz dieser Maschine</translation>
    </message>
    <message>
        <source>The table does not say which reference tool T%1&apos;s TLO was measured against: make sure it is the reference the machine has now.</source>
        <translation>Die Tabelle sagt nicht, gegen welches Referenzwerkzeug die TLO von T%1 gemessen wurde: Stellen Sie sicher, dass es die Referenz ist, die die Maschine jetzt hat.</translation>
    </message>
    <message>
        <source>The spindle is empty: load a tool first (Rack ▸ Load).</source>
        <translation>Die Spindel ist leer: Wechseln Sie zuerst ein Werkzeug ein (Magazin ▸ Einwechseln).</translation>
    </message>
    <message>
        <source>The machine will move: up to clearance, over the tool setter, then down until %1 touches it. Keep hands clear.

The machine says %1 is in the spindle: the measurement is recorded as %1&apos;s TLO.

Probe now?</source>
        <translation>Die Maschine fährt: auf Sicherheitshöhe, über den Werkzeugtaster, dann hinunter, bis %1 ihn berührt. Hände weg.

Die Maschine meldet %1 in der Spindel: Die Messung wird als Längenkorrektur von %1 aufgezeichnet.

Jetzt vermessen?</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was measured against a reference tool at MCS Z %3, but the machine&apos;s reference is now at MCS Z %4 (another machine&apos;s TLO, or the machine was calibrated again since). Restored, it would be off by %5.

Probe T%1 instead.</source>
        <translation>Die Längenkorrektur %2 von T%1 wurde gegen ein Referenzwerkzeug bei MCS Z %3 gemessen, die Referenz der Maschine liegt jetzt aber bei MCS Z %4 (die Längenkorrektur einer anderen Maschine, oder die Maschine wurde seitdem neu kalibriert). Zurückgesetzt läge sie um %5 daneben.

Vermessen Sie T%1 stattdessen.</translation>
    </message>
    <message>
        <source>The machine reports no reference tool MCS Z: a stored TLO is only right against the reference it was measured from.</source>
        <translation>Die Maschine meldet keine Referenz-MCS-Z: Eine gespeicherte Längenkorrektur stimmt nur gegen die Referenz, gegen die sie gemessen wurde.</translation>
    </message>
    <message>
        <source>Sends: %1</source>
        <translation>Sendet: %1</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was set by hand, not measured on the tool setter.</source>
        <translation>Die TL von T%1 wurde von Hand gesetzt, nicht am Werkzeugtaster gemessen.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO is dated in the future (%2): a clock was wrong, and when it was measured is not known.</source>
        <translation>Die TL von T%1 ist in der Zukunft datiert (%2): Eine Uhr ging falsch, und wann sie gemessen wurde, ist unbekannt.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO is %2 days old, older than the stale limit (%3 d): the cutter may have worn or been changed since.</source>
        <translation>Die TL von T%1 ist %2 Tage alt, älter als die Veraltungsgrenze (%3 d): Der Fräser kann seither verschlissen oder gewechselt worden sein.</translation>
    </message>
    <message>
        <source>This machine has no reference tool yet: %1 becomes it (TLO 0.000), and every tool measured after it gets its length against %1&apos;s. Probe the tool you mean to keep as the reference.</source>
        <translation>Diese Maschine hat noch kein Referenzwerkzeug: %1 wird es (TLO 0,000), und jedes danach gemessene Werkzeug erhält seine Länge gegenüber %1. Messen Sie das Werkzeug, das Referenz bleiben soll.</translation>
    </message>
    <message>
        <source>read from the controller</source>
        <translation>aus der Steuerung gelesen</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was read from the controller&apos;s table, not measured on the tool setter.</source>
        <translation>Die TLO von T%1 wurde aus der Tabelle der Steuerung gelesen, nicht am Werkzeugtaster gemessen.</translation>
    </message>
    <message>
        <source>The machine says no tool is in the spindle (T0), so there is nothing to probe. Say which tool is in first (the table&apos;s context menu: Make Active).</source>
        <translation>Die Maschine meldet kein Werkzeug in der Spindel (T0), also gibt es nichts anzutasten. Geben Sie zuerst an, welches Werkzeug eingesetzt ist (Kontextmenü der Tabelle: Aktiv machen).</translation>
    </message>
    <message>
        <source>Nothing to probe</source>
        <translation>Nichts anzutasten</translation>
    </message>
    <message>
        <source>As its settings say: %1.</source>
        <translation>Wie seine Einstellungen sagen: %1.</translation>
    </message>
</context>
<context>
    <name>Toffee::ProbePlan</name>
    <message>
        <source>%1 touches</source>
        <translation>%1 Antastungen</translation>
    </message>
    <message>
        <source>X %1 Y %2 mm from the setter&apos;s centre</source>
        <translation>X %1 Y %2 mm von der Mitte des Längenmessgeräts</translation>
    </message>
    <message>
        <source>latch at %1 mm/min</source>
        <translation>Feinvorschub %1 mm/min</translation>
    </message>
</context>
<context>
    <name>Toffee::ProbeSettings</name>
    <message>
        <source>A touch-off point lies at most %1 %2 from the setter&apos;s centre in X and Y.</source>
        <translation>Ein Antastpunkt liegt in X und Y höchstens %1 %2 von der Mitte des Längenmessgeräts.</translation>
    </message>
    <message>
        <source>A tool is touched 1 to %1 times.</source>
        <translation>Ein Werkzeug wird 1- bis %1-mal angetastet.</translation>
    </message>
    <message>
        <source>A latch feed must be more than 0 and at most %1 %2/min.</source>
        <translation>Ein Feinvorschub muss größer als 0 und höchstens %1 %2/min sein.</translation>
    </message>
    <message>
        <source>A spread limit must be more than 0 and at most %1 %2.</source>
        <translation>Eine Streuungsgrenze muss größer als 0 und höchstens %1 %2 sein.</translation>
    </message>
    <message>
        <source>X %1</source>
        <translation>X %1</translation>
    </message>
    <message>
        <source>Y %1</source>
        <translation>Y %1</translation>
    </message>
    <message>
        <source>1 edge</source>
        <translation>1 Schneide</translation>
    </message>
    <message>
        <source>%1 edges</source>
        <translation>%1 Schneiden</translation>
    </message>
    <message>
        <source>1 touch</source>
        <translation>1 Antastung</translation>
    </message>
    <message>
        <source>%1 touches</source>
        <translation>%1 Antastungen</translation>
    </message>
    <message>
        <source>same edge</source>
        <translation>gleiche Schneide</translation>
    </message>
    <message>
        <source>latch %1</source>
        <translation>Feinvorschub %1</translation>
    </message>
    <message>
        <source>spread %1</source>
        <translation>Streuung %1</translation>
    </message>
    <message>
        <source>Type how the tool is measured, any of: &quot;X 30&quot; and &quot;Y 0&quot; (the touch-off point from the setter&apos;s centre), &quot;4 edges&quot;, &quot;4 touches&quot;, &quot;same edge&quot; (no turn between touches), &quot;latch 20&quot; (the slow touch&apos;s feed per minute), &quot;spread 0.02&quot; (the widest spread that is no finding), separated by commas; empty for one touch at the centre.</source>
        <translation>Geben Sie ein, wie das Werkzeug gemessen wird, beliebig aus: „X 30“ und „Y 0“ (der Antastpunkt von der Mitte des Längenmessgeräts), „4 Schneiden“, „4 Antastungen“, „gleiche Schneide“ (keine Drehung zwischen Antastungen), „Feinvorschub 20“ (der Vorschub der langsamen Antastung pro Minute), „Streuung 0.02“ (die größte Streuung, die kein Befund ist), durch Kommas getrennt; leer für eine Antastung in der Mitte.</translation>
    </message>
    <message>
        <source>touches</source>
        <translation>Antastungen</translation>
    </message>
    <message>
        <source>touch</source>
        <translation>Antastung</translation>
    </message>
    <message>
        <source>edges</source>
        <translation>Schneiden</translation>
    </message>
    <message>
        <source>edge</source>
        <translation>Schneide</translation>
    </message>
    <message>
        <source>flutes</source>
        <translation>Zähne</translation>
    </message>
    <message>
        <source>latch</source>
        <translation>Feinvorschub</translation>
    </message>
    <message>
        <source>spread</source>
        <translation>Streuung</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a probing setting. %2</source>
        <translation>„%1“ ist keine Antasteinstellung. %2</translation>
    </message>
    <message>
        <source>A cutter has 1 to %1 cutting edges.</source>
        <translation>Ein Fräser hat 1 bis %1 Schneiden.</translation>
    </message>
</context>
<context>
    <name>Toffee::ProgramUse</name>
    <message>
        <source>%1 Nothing was recorded.</source>
        <translation>%1 Es wurde nichts aufgezeichnet.</translation>
    </message>
</context>
<context>
    <name>Toffee::PtyServer</name>
    <message>
        <source>cannot open a pseudo-terminal: %1</source>
        <translation>Kein Pseudoterminal verfügbar: %1</translation>
    </message>
    <message>
        <source>cannot make the link %1</source>
        <translation>Der Link %1 lässt sich nicht anlegen</translation>
    </message>
</context>
<context>
    <name>Toffee::RackPanel</name>
    <message>
        <source>Measure Rack…</source>
        <translation>Magazin vermessen …</translation>
    </message>
    <message>
        <source>Check Rack…</source>
        <translation>Magazin prüfen …</translation>
    </message>
    <message>
        <source>After a manual change, use the tool&apos;s stored TLO
when it is fresh (no probe)</source>
        <translation>Nach einem manuellen Wechsel die gespeicherte TLO
verwenden, wenn sie nicht veraltet ist (ohne Vermessen)</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>The tool in the spindle</source>
        <translation>Das Werkzeug in der Spindel</translation>
    </message>
    <message>
        <source>The machine&apos;s firmware</source>
        <translation>Die Firmware der Maschine</translation>
    </message>
    <message>
        <source>The tools the rack holds</source>
        <translation>Die Werkzeuge im Magazin</translation>
    </message>
    <message>
        <source>Why the rack is not understood</source>
        <translation>Warum das Magazin nicht verstanden wird</translation>
    </message>
    <message>
        <source>The rack&apos;s tools</source>
        <translation>Die Werkzeuge des Magazins</translation>
    </message>
    <message>
        <source>The tool to load</source>
        <translation>Das einzuwechselnde Werkzeug</translation>
    </message>
    <message>
        <source>Load the tool</source>
        <translation>Das Werkzeug einwechseln</translation>
    </message>
    <message>
        <source>Measure every rack tool</source>
        <translation>Jedes Magazinwerkzeug vermessen</translation>
    </message>
    <message>
        <source>Break-test every rack tool</source>
        <translation>Bruchtest für jedes Magazinwerkzeug</translation>
    </message>
    <message>
        <source>Rack check tolerance in millimetres</source>
        <translation>Toleranz der Magazinprüfung in Millimetern</translation>
    </message>
    <message>
        <source>Use a fresh stored TLO after a manual change</source>
        <translation>Nach einem manuellen Wechsel eine nicht veraltete gespeicherte TLO verwenden</translation>
    </message>
    <message>
        <source>Rack progress</source>
        <translation>Fortschritt des Magazinvorgangs</translation>
    </message>
    <message>
        <source>What the machine does now</source>
        <translation>Was die Maschine gerade tut</translation>
    </message>
    <message>
        <source>Cancel the rack operation</source>
        <translation>Den Magazinvorgang abbrechen</translation>
    </message>
    <message>
        <source>The last rack operation&apos;s result</source>
        <translation>Das Ergebnis des letzten Magazinvorgangs</translation>
    </message>
    <message>
        <source>1-6 on a Carvera C1, or tool numbers and ranges (1,2,5-8); the job check uses the same rack.</source>
        <translation>1-6 bei einer Carvera C1 oder Werkzeugnummern und Bereiche (1,2,5-8); die Jobprüfung verwendet dasselbe Magazin.</translation>
    </message>
    <message>
        <source>1-6, or none</source>
        <translation>1-6 oder none</translation>
    </message>
    <message>
        <source>Any tool: one outside the rack is a manual change</source>
        <translation>Beliebiges Werkzeug: Eines außerhalb des Magazins ist ein manueller Wechsel</translation>
    </message>
    <message>
        <source>A rack tool is always measured by the machine at its change.</source>
        <translation>Ein Magazinwerkzeug wird von der Maschine bei seinem Wechsel immer vermessen.</translation>
    </message>
    <message>
        <source>%v of %m</source>
        <translation>%v von %m</translation>
    </message>
    <message>
        <source>&amp;Rack holds:</source>
        <translation>&amp;Magazin enthält:</translation>
    </message>
    <message>
        <source>Connect to the machine first.</source>
        <translation>Zuerst mit der Maschine verbinden.</translation>
    </message>
    <message>
        <source>Load T%1…</source>
        <translation>T%1 einwechseln …</translation>
    </message>
    <message>
        <source>Break-test every rack tool against its stored TLO; the machine halts on a broken one.</source>
        <translation>Bruchtest für jedes Magazinwerkzeug gegen seine gespeicherte TLO; bei einem gebrochenen hält die Maschine an.</translation>
    </message>
    <message>
        <source>Change to every rack tool in turn and measure it on the tool setter.</source>
        <translation>Nacheinander zu jedem Magazinwerkzeug wechseln und es am Werkzeugtaster vermessen.</translation>
    </message>
    <message>
        <source>Change to the tool: the machine puts the one in the spindle back first.</source>
        <translation>Zu dem Werkzeug wechseln: Die Maschine legt zuerst das Werkzeug aus der Spindel zurück.</translation>
    </message>
    <message>
        <source>Spindle: unknown</source>
        <translation>Spindel: unbekannt</translation>
    </message>
    <message>
        <source>Spindle: empty</source>
        <translation>Spindel: leer</translation>
    </message>
    <message>
        <source>Spindle: T%1</source>
        <translation>Spindel: T%1</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>%1 — no break test</source>
        <translation>%1 — kein Bruchtest</translation>
    </message>
    <message>
        <source>T%1 is in the spindle already: the machine measures it again on the tool setter.</source>
        <translation>T%1 ist bereits in der Spindel: Die Maschine vermisst es erneut am Werkzeugtaster.</translation>
    </message>
    <message>
        <source>The machine puts T%1 back in the rack, picks T%2 and measures it on the tool setter.</source>
        <translation>Die Maschine legt T%1 ins Magazin zurück, nimmt T%2 auf und vermisst es am Werkzeugtaster.</translation>
    </message>
    <message>
        <source>The machine puts T%1 back in the rack.</source>
        <translation>Die Maschine legt T%1 ins Magazin zurück.</translation>
    </message>
    <message>
        <source>T%1 has no slot in the rack: take it out of the spindle when the machine asks.</source>
        <translation>T%1 hat keinen Platz im Magazin: Nehmen Sie es aus der Spindel, wenn die Maschine dazu auffordert.</translation>
    </message>
    <message>
        <source>The machine picks T%1 from the rack and measures it on the tool setter.</source>
        <translation>Die Maschine nimmt T%1 aus dem Magazin und vermisst es am Werkzeugtaster.</translation>
    </message>
    <message>
        <source>T%1 has no slot in the rack: put it in the spindle when the machine asks. The machine then takes its stored TLO %2 (measured %3) and does not probe it.</source>
        <translation>T%1 hat keinen Platz im Magazin: Setzen Sie es in die Spindel, wenn die Maschine dazu auffordert. Die Maschine übernimmt dann seine gespeicherte TLO %2 (gemessen %3) und vermisst es nicht.</translation>
    </message>
    <message>
        <source>T%1 has no slot in the rack: put it in the spindle when the machine asks. The machine then measures it on the tool setter.</source>
        <translation>T%1 hat keinen Platz im Magazin: Setzen Sie es in die Spindel, wenn die Maschine dazu auffordert. Die Maschine vermisst es dann am Werkzeugtaster.</translation>
    </message>
    <message>
        <source>The stored TLO is not used: %1</source>
        <translation>Die gespeicherte TLO wird nicht verwendet: %1</translation>
    </message>
    <message>
        <source>Keep clear of the machine.</source>
        <translation>Halten Sie Abstand zur Maschine.</translation>
    </message>
    <message>
        <source>Load T%1?</source>
        <translation>T%1 einwechseln?</translation>
    </message>
    <message>
        <source>Loading T%1 failed</source>
        <translation>Einwechseln von T%1 fehlgeschlagen</translation>
    </message>
    <message>
        <source>Nothing was written to the tool table.</source>
        <translation>In die Werkzeugtabelle wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>T%1 is in the spindle with TLO %2, but it could not be recorded: %3</source>
        <translation>T%1 ist mit TLO %2 in der Spindel, konnte aber nicht gespeichert werden: %3</translation>
    </message>
    <message>
        <source>T%1 takes its stored TLO %2 (measured %3); not probed.</source>
        <translation>T%1 übernimmt seine gespeicherte TLO %2 (gemessen %3); nicht vermessen.</translation>
    </message>
    <message>
        <source>T%1 measured: TLO %2, recorded in the table.</source>
        <translation>T%1 gemessen: TLO %2, in der Tabelle gespeichert.</translation>
    </message>
    <message>
        <source>Stopping after this tool…</source>
        <translation>Halt nach diesem Werkzeug …</translation>
    </message>
    <message>
        <source>Stop the machine?</source>
        <translation>Maschine anhalten?</translation>
    </message>
    <message>
        <source>Stop the machine now? It halts; Unlock afterwards.</source>
        <translation>Die Maschine jetzt anhalten? Sie hält an; danach Entsperren.</translation>
    </message>
    <message>
        <source>Check the rack?</source>
        <translation>Das Magazin prüfen?</translation>
    </message>
    <message>
        <source>Measure the rack?</source>
        <translation>Das Magazin vermessen?</translation>
    </message>
    <message>
        <source>The machine changes to %1 in turn and break-tests each against its stored TLO (tolerance %2). A broken tool halts the machine and stops the check. After the last, T%3 goes back in the rack.</source>
        <translation>Die Maschine wechselt nacheinander zu %1 und prüft jedes per Bruchtest gegen seine gespeicherte TLO (Toleranz %2). Ein gebrochenes Werkzeug hält die Maschine an und beendet die Prüfung. Nach dem letzten kommt T%3 zurück ins Magazin.</translation>
    </message>
    <message>
        <source>The machine changes to %1 in turn, putting the tool in the spindle back in the rack first, and measures each on the tool setter; each TLO is recorded in the table. T%2 stays in the spindle.</source>
        <translation>Die Maschine wechselt nacheinander zu %1, legt dabei zuerst das Werkzeug aus der Spindel ins Magazin zurück und vermisst jedes am Werkzeugtaster; jede TLO wird in der Tabelle gespeichert. T%2 bleibt in der Spindel.</translation>
    </message>
    <message>
        <source>T%1: %2</source>
        <translation>T%1: %2</translation>
    </message>
    <message>
        <source>Not run: %1.</source>
        <translation>Nicht ausgeführt: %1.</translation>
    </message>
    <message>
        <source>A measurement could not be stored in the table, so the rack was stopped: %1</source>
        <translation>Eine Messung konnte nicht in der Tabelle gespeichert werden, daher wurde der Magazinvorgang angehalten: %1</translation>
    </message>
    <message>
        <source>The rack was stopped</source>
        <translation>Der Magazinvorgang wurde angehalten</translation>
    </message>
    <message>
        <source>The rack check failed</source>
        <translation>Die Magazinprüfung ist fehlgeschlagen</translation>
    </message>
    <message>
        <source>Measuring the rack failed</source>
        <translation>Das Vermessen des Magazins ist fehlgeschlagen</translation>
    </message>
    <message>
        <source>Rack checked: 1 tool passed.</source>
        <translation>Magazin geprüft: 1 Werkzeug bestanden.</translation>
    </message>
    <message>
        <source>Rack checked: %1 tools passed.</source>
        <translation>Magazin geprüft: %1 Werkzeuge bestanden.</translation>
    </message>
    <message>
        <source>Rack measured: 1 tool, its TLO recorded in the table.</source>
        <translation>Magazin vermessen: 1 Werkzeug, seine TLO in der Tabelle gespeichert.</translation>
    </message>
    <message>
        <source>Rack measured: %1 tools, each TLO recorded in the table.</source>
        <translation>Magazin vermessen: %1 Werkzeuge, jede TLO in der Tabelle gespeichert.</translation>
    </message>
    <message>
        <source>The tool</source>
        <translation>Das Werkzeug</translation>
    </message>
    <message>
        <source>%1 may be broken: the check stopped and the machine halted.</source>
        <translation>%1 ist möglicherweise gebrochen: Die Prüfung wurde beendet, und die Maschine hat angehalten.</translation>
    </message>
    <message>
        <source>%1 may be broken</source>
        <translation>%1 ist möglicherweise gebrochen</translation>
    </message>
    <message>
        <source>%1 may be broken. The rack check stopped there, and the machine has halted.</source>
        <translation>%1 ist möglicherweise gebrochen. Die Magazinprüfung wurde dort beendet, und die Maschine hat angehalten.</translation>
    </message>
    <message>
        <source>The table marks %1 until it is measured again: once it is checked or replaced and the machine unlocked (the strip&apos;s Unlock, Ctrl+Shift+U), measure it with Load Tool or Measure Rack.</source>
        <translation>Die Tabelle markiert %1, bis es erneut vermessen wird: Sobald es geprüft oder ersetzt und die Maschine entsperrt ist (Entsperren in der Leiste, Strg+Umschalt+U), vermessen Sie es mit „Einwechseln“ oder „Magazin vermessen“.</translation>
    </message>
    <message>
        <source>Slot</source>
        <translation>Platz</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>Stored TLO</source>
        <translation>Gespeicherte TLO</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Gemessen</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <source>In millimetres</source>
        <translation>In Millimetern</translation>
    </message>
    <message>
        <source>This session&apos;s Measure Rack or Check Rack, with the TLO measured (mm)</source>
        <translation>„Magazin vermessen“ oder „Magazin prüfen“ dieser Sitzung, mit der gemessenen TLO (mm)</translation>
    </message>
    <message>
        <source>never</source>
        <translation>nie</translation>
    </message>
    <message>
        <source>failed break test</source>
        <translation>Bruchtest nicht bestanden</translation>
    </message>
    <message>
        <source>set by hand</source>
        <translation>von Hand gesetzt</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <source>T%1 · in spindle</source>
        <translation>T%1 · in der Spindel</translation>
    </message>
    <message>
        <source>Not in the table</source>
        <translation>Nicht in der Tabelle</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>Wartet</translation>
    </message>
    <message>
        <source>Checking…</source>
        <translation>Wird geprüft …</translation>
    </message>
    <message>
        <source>Measuring…</source>
        <translation>Wird vermessen …</translation>
    </message>
    <message>
        <source>Measured: %1</source>
        <translation>Gemessen: %1</translation>
    </message>
    <message>
        <source>Passed</source>
        <translation>Bestanden</translation>
    </message>
    <message>
        <source>Passed: %1</source>
        <translation>Bestanden: %1</translation>
    </message>
    <message>
        <source>BROKEN</source>
        <translation>GEBROCHEN</translation>
    </message>
    <message>
        <source>BROKEN: %1</source>
        <translation>GEBROCHEN: %1</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>Fehlgeschlagen</translation>
    </message>
    <message>
        <source>Not run</source>
        <translation>Nicht ausgeführt</translation>
    </message>
    <message>
        <source>Empty</source>
        <translation>Leer</translation>
    </message>
    <message>
        <source>Empty the Spindle…</source>
        <translation>Spindel leeren …</translation>
    </message>
    <message>
        <source>The machine puts T%1 back in the rack; the spindle stays empty.</source>
        <translation>Die Maschine legt T%1 ins Magazin zurück; die Spindel bleibt leer.</translation>
    </message>
    <message>
        <source>Take the tool out of the spindle when the machine asks; the spindle stays empty.</source>
        <translation>Nehmen Sie das Werkzeug aus der Spindel, wenn die Maschine dazu auffordert; die Spindel bleibt leer.</translation>
    </message>
    <message>
        <source>Empty the spindle?</source>
        <translation>Spindel leeren?</translation>
    </message>
    <message>
        <source>The spindle is empty.</source>
        <translation>Die Spindel ist leer.</translation>
    </message>
    <message>
        <source>The machine stopped during T%1&apos;s step: look which tool is in the spindle and that the rack holds the others before you Unlock, then measure the tool in the spindle.</source>
        <translation>Die Maschine hat während des Schritts von T%1 angehalten: Sehen Sie nach, welches Werkzeug in der Spindel steckt und ob das Magazin die übrigen hält, bevor Sie entsperren; vermessen Sie dann das Werkzeug in der Spindel.</translation>
    </message>
    <message>
        <source>Skipped</source>
        <translation>Übersprungen</translation>
    </message>
    <message>
        <source>%1 has no tool rack: the rack is the Carvera&apos;s.</source>
        <translation>%1 hat kein Werkzeugmagazin: Das Magazin gehört zur Carvera.</translation>
    </message>
    <message>
        <source>read from the controller</source>
        <translation>aus der Steuerung gelesen</translation>
    </message>
</context>
<context>
    <name>Toffee::RackSequence</name>
    <message>
        <source>The rack holds no tools: say which tools it holds (1-6 on a C1) first.</source>
        <translation>Das Magazin enthält keine Werkzeuge: Geben Sie zuerst an, welche Werkzeuge es enthält (1-6 bei einer C1).</translation>
    </message>
    <message>
        <source>The machine runs %1, whose M491.1 only measures a tool again without comparing: a rack check there would pass a broken tool. Install the community firmware to check the rack.</source>
        <translation>Auf der Maschine läuft %1, deren M491.1 ein Werkzeug nur erneut vermisst, ohne zu vergleichen: Eine Magazinprüfung würde dort ein gebrochenes Werkzeug bestehen lassen. Installieren Sie die Community-Firmware, um das Magazin zu prüfen.</translation>
    </message>
    <message>
        <source>The machine did not say which firmware it runs, so Toffee cannot tell whether its M491.1 compares a tool with its TLO. The rack was not checked.</source>
        <translation>Die Maschine hat nicht angegeben, welche Firmware sie verwendet, daher kann Toffee nicht erkennen, ob ihr M491.1 ein Werkzeug mit seiner TLO vergleicht. Das Magazin wurde nicht geprüft.</translation>
    </message>
    <message>
        <source>%1 have no stored TLO to compare with. Measure them first (Measure Rack); nothing moved.</source>
        <translation>%1 haben keine gespeicherte TLO zum Vergleichen. Vermessen Sie sie zuerst (Magazin vermessen); nichts hat sich bewegt.</translation>
    </message>
    <message>
        <source>Measuring the rack…</source>
        <translation>Magazin wird vermessen …</translation>
    </message>
    <message>
        <source>Checking the rack…</source>
        <translation>Magazin wird geprüft …</translation>
    </message>
    <message>
        <source>The machine is busy or not connected.</source>
        <translation>Die Maschine ist beschäftigt oder nicht verbunden.</translation>
    </message>
    <message>
        <source>Measuring T%1 (%2 of %3)…</source>
        <translation>Vermesse T%1 (%2 von %3) …</translation>
    </message>
    <message>
        <source>Checking T%1 (%2 of %3)…</source>
        <translation>Prüfe T%1 (%2 von %3) …</translation>
    </message>
    <message>
        <source>The connection to the machine was closed; the rack was not finished.</source>
        <translation>Die Verbindung zur Maschine wurde geschlossen; der Magazinvorgang wurde nicht abgeschlossen.</translation>
    </message>
    <message>
        <source>Cancelled after the last tool: every tool was done, and T%1 stays in the spindle.</source>
        <translation>Nach dem letzten Werkzeug abgebrochen: Alle Werkzeuge sind erledigt, und T%1 bleibt in der Spindel.</translation>
    </message>
    <message>
        <source>Cancelled: the rack was stopped after T%1, which is in the spindle.</source>
        <translation>Abgebrochen: Der Magazinvorgang wurde nach T%1 angehalten, das in der Spindel ist.</translation>
    </message>
    <message>
        <source>Putting T%1 back in the rack…</source>
        <translation>T%1 wird ins Magazin zurückgelegt …</translation>
    </message>
    <message>
        <source>Every tool passed, but the last one could not be put back: %1</source>
        <translation>Alle Werkzeuge haben bestanden, aber das letzte konnte nicht zurückgelegt werden: %1</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO was measured against reference MCS Z %2, but the machine&apos;s reference is at %3 now, %4 away: every comparison would be off by that much. Check the machine&apos;s calibration and the tool setter; if they are sound, measure the rack again (Measure Rack).</source>
        <translation>Die gespeicherte Längenkorrektur von T%1 wurde gegen Referenz-MCS-Z %2 gemessen, die Referenz der Maschine liegt jetzt aber bei %3, %4 entfernt: Jeder Vergleich läge um so viel daneben. Prüfen Sie die Kalibrierung der Maschine und den Werkzeugtaster; sind sie in Ordnung, vermessen Sie das Magazin erneut (Magazin vermessen).</translation>
    </message>
</context>
<context>
    <name>Toffee::RemoveToolsCommand</name>
    <message>
        <source>Remove tool T%1</source>
        <translation>Werkzeug T%1 entfernen</translation>
    </message>
    <message>
        <source>Remove %1 tools</source>
        <translation>%1 Werkzeuge entfernen</translation>
    </message>
</context>
<context>
    <name>Toffee::RowReader</name>
    <message>
        <source>a blob of %1 bytes</source>
        <translation>ein Blob von %1 Byte</translation>
    </message>
    <message>
        <source>a row&apos;s tool number is %1, not a tool number (%2 to %3)</source>
        <translation>die Werkzeugnummer einer Zeile ist %1, keine Werkzeugnummer (%2 bis %3)</translation>
    </message>
    <message>
        <source>T%1&apos;s row</source>
        <translation>Zeile von T%1</translation>
    </message>
    <message>
        <source>its version is %1, not a whole number from 1 up</source>
        <translation>ihre Version ist %1, keine ganze Zahl ab 1</translation>
    </message>
    <message>
        <source>&quot;deleted&quot; is %1, not 0 or 1</source>
        <translation>„deleted“ ist %1, nicht 0 oder 1</translation>
    </message>
    <message>
        <source>its data is %1 characters long; no tool&apos;s is longer than %2 KB</source>
        <translation>ihre Daten sind %1 Zeichen lang; die keines Werkzeugs sind länger als %2 KB</translation>
    </message>
    <message>
        <source>its data is %1, not a tool</source>
        <translation>ihre Daten sind %1, kein Werkzeug</translation>
    </message>
    <message>
        <source>its data is T%1&apos;s, not T%2&apos;s</source>
        <translation>ihre Daten gehören zu T%1, nicht zu T%2</translation>
    </message>
    <message>
        <source>event %1: %2</source>
        <translation>Ereignis %1: %2</translation>
    </message>
    <message>
        <source>its id is not an event&apos;s</source>
        <translation>ihre Kennung ist keine eines Ereignisses</translation>
    </message>
    <message>
        <source>it names no machine</source>
        <translation>es nennt keine Maschine</translation>
    </message>
    <message>
        <source>its tool %1 is not a tool number</source>
        <translation>sein Werkzeug %1 ist keine Werkzeugnummer</translation>
    </message>
    <message>
        <source>it has no valid time</source>
        <translation>es hat keine gültige Zeit</translation>
    </message>
    <message>
        <source>its %1 is %2, which no machine measures</source>
        <translation>sein Wert %1 ist %2, was keine Maschine misst</translation>
    </message>
    <message>
        <source>its tolerance is negative</source>
        <translation>seine Toleranz ist negativ</translation>
    </message>
    <message>
        <source>an event&apos;s row has %1 columns, not %2</source>
        <translation>die Zeile eines Ereignisses hat %1 Spalten, nicht %2</translation>
    </message>
    <message>
        <source>its id is not text of up to %1 characters</source>
        <translation>seine Kennung ist kein Text von höchstens %1 Zeichen</translation>
    </message>
    <message>
        <source>its machine is %1, not a machine&apos;s name</source>
        <translation>seine Maschine ist %1, kein Maschinenname</translation>
    </message>
    <message>
        <source>its tool is %1, not a tool number (%2 to %3)</source>
        <translation>sein Werkzeug ist %1, keine Werkzeugnummer (%2 bis %3)</translation>
    </message>
    <message>
        <source>its time is %1, not a time in UTC (2026-11-23T08:10:00.125Z)</source>
        <translation>seine Zeit ist %1, keine Zeit in UTC (2026-11-23T08:10:00.125Z)</translation>
    </message>
    <message>
        <source>its kind is %1, not one Toffee records</source>
        <translation>seine Art ist %1, keine, die Toffee aufzeichnet</translation>
    </message>
    <message>
        <source>its %1 is %2, not a number</source>
        <translation>sein Wert %1 ist %2, keine Zahl</translation>
    </message>
    <message>
        <source>&quot;failed&quot; is %1, not 0 or 1</source>
        <translation>„failed“ ist %1, nicht 0 oder 1</translation>
    </message>
    <message>
        <source>a tool use&apos;s row has %1 columns, not 7</source>
        <translation>die Zeile einer Werkzeugnutzung hat %1 Spalten, nicht 7</translation>
    </message>
    <message>
        <source>tool use %1: %2</source>
        <translation>Werkzeugnutzung %1: %2</translation>
    </message>
    <message>
        <source>its tool is %1, not a tool number</source>
        <translation>sein Werkzeug ist %1, keine Werkzeugnummer</translation>
    </message>
    <message>
        <source>its time is %1, not a time in UTC</source>
        <translation>seine Zeit ist %1, keine Zeit in UTC</translation>
    </message>
    <message>
        <source>its program is %1, not a file name</source>
        <translation>sein Programm ist %1, kein Dateiname</translation>
    </message>
    <message>
        <source>its cutting time is %1, not a number of seconds</source>
        <translation>seine Schnittzeit ist %1, keine Anzahl Sekunden</translation>
    </message>
    <message>
        <source>its feed path is %1, not a length</source>
        <translation>sein Vorschubweg ist %1, keine Länge</translation>
    </message>
    <message>
        <source>its touches are not 2 to %1 machine positions</source>
        <translation>seine Antastungen sind nicht 2 bis %1 Maschinenpositionen</translation>
    </message>
    <message>
        <source>its touches are %1, not machine positions</source>
        <translation>seine Antastungen sind %1, keine Maschinenpositionen</translation>
    </message>
</context>
<context>
    <name>Toffee::SelfTest</name>
    <message>
        <source>no progress within 20 s</source>
        <translation>kein Fortschritt innerhalb von 20 s</translation>
    </message>
    <message>
        <source>self-test failed while %1: %2</source>
        <translation>Selbsttest fehlgeschlagen beim Schritt „%1“: %2</translation>
    </message>
    <message>
        <source>showing the window</source>
        <translation>Fenster anzeigen</translation>
    </message>
    <message>
        <source>the window did not render</source>
        <translation>Das Fenster wurde nicht gezeichnet</translation>
    </message>
    <message>
        <source>loading the example table</source>
        <translation>Beispieltabelle laden</translation>
    </message>
    <message>
        <source>the example table did not load</source>
        <translation>Die Beispieltabelle wurde nicht geladen</translation>
    </message>
    <message>
        <source>connecting to the built-in emulator</source>
        <translation>Mit dem eingebauten Emulator verbinden</translation>
    </message>
    <message>
        <source>probing the current tool</source>
        <translation>Aktuelles Werkzeug vermessen</translation>
    </message>
    <message>
        <source>the measurement did not reach the table</source>
        <translation>Die Messung ist nicht in der Tabelle angekommen</translation>
    </message>
    <message>
        <source>rendering</source>
        <translation>Zeichnen</translation>
    </message>
    <message>
        <source>self-test passed: first frame after %1 ms; T%2 probed, TLO %3 mm recorded</source>
        <translation>Selbsttest bestanden: erstes Bild nach %1 ms; T%2 vermessen, Längenkorrektur %3 mm gespeichert</translation>
    </message>
</context>
<context>
    <name>Toffee::SerialPortTransport</name>
    <message>
        <source>Cannot open %1: %2. Check the cable, that no other program has the port open, and that you may use serial ports (the dialout group).</source>
        <translation>%1 lässt sich nicht öffnen: %2. Prüfen Sie das Kabel, ob ein anderes Programm den Anschluss geöffnet hat und ob Sie serielle Anschlüsse verwenden dürfen (Gruppe dialout).</translation>
    </message>
    <message>
        <source>%1 at %2 baud</source>
        <translation>%1 mit %2 Baud</translation>
    </message>
    <message>
        <source>The port %1 stopped answering and was closed: the cable was unplugged, the machine switched off, or the program serving the port ended. Check the cable and the machine, then connect again.</source>
        <translation>Der Anschluss %1 antwortet nicht mehr und wurde geschlossen: Das Kabel wurde abgezogen, die Maschine ausgeschaltet oder das Programm hinter dem Anschluss beendet. Prüfen Sie Kabel und Maschine und verbinden Sie erneut.</translation>
    </message>
    <message>
        <source>The port %1 failed (%2); the link was closed. Check the cable and connect again.</source>
        <translation>Der Anschluss %1 ist ausgefallen (%2); die Verbindung wurde geschlossen. Prüfen Sie das Kabel und verbinden Sie erneut.</translation>
    </message>
</context>
<context>
    <name>Toffee::SetterCycle</name>
    <message>
        <source>The tool&apos;s latch feed (%1 mm/min) must not be faster than the setter&apos;s search feed (%2 mm/min).</source>
        <translation>Der Feinvorschub des Werkzeugs (%1 mm/min) darf nicht schneller sein als der Suchvorschub des Längenmessgeräts (%2 mm/min).</translation>
    </message>
    <message>
        <source>The tool&apos;s touch-off point (X %1, Y %2 mm) lies beyond the machine&apos;s coordinates.</source>
        <translation>Der Antastpunkt des Werkzeugs (X %1, Y %2 mm) liegt außerhalb der Maschinenkoordinaten.</translation>
    </message>
    <message>
        <source>%1 cannot turn its spindle to an angle, so the %2 touches met the setter wherever the spindle stood: their spread is the setter&apos;s repeatability and the cutter&apos;s runout there, not each edge&apos;s.</source>
        <translation>%1 kann seine Spindel nicht auf einen Winkel drehen, daher trafen die %2 Antastungen das Längenmessgerät, wo die Spindel stand: Ihre Streuung ist die Wiederholgenauigkeit des Geräts und der Rundlauf des Fräsers dort, nicht die jeder Schneide.</translation>
    </message>
</context>
<context>
    <name>Toffee::Spool</name>
    <message>
        <source>The folder %1 cannot be made, so nothing can be kept there.</source>
        <translation>Der Ordner %1 lässt sich nicht anlegen; darin kann nichts aufbewahrt werden.</translation>
    </message>
    <message>
        <source>%1 was written to the library but cannot be removed from this computer; it will be sent again, and the library will find it already there.</source>
        <translation>%1 wurde in die Bibliothek geschrieben, lässt sich aber von diesem Computer nicht entfernen; es wird erneut gesendet, und die Bibliothek findet es dann schon vor.</translation>
    </message>
    <message>
        <source>%1 is not a measurement Toffee kept: it was changed or damaged.</source>
        <translation>%1 ist keine Messung, die Toffee aufbewahrt hat: Sie wurde verändert oder beschädigt.</translation>
    </message>
    <message>
        <source>There is nothing to keep.</source>
        <translation>Es gibt nichts aufzubewahren.</translation>
    </message>
    <message>
        <source>It was moved to %1.</source>
        <translation>Sie wurde nach %1 verschoben.</translation>
    </message>
    <message>
        <source>%1 event(s) of %2 cannot go into the history (%3). They were moved to %4 apart; the file&apos;s other events are sent.</source>
        <translation>%1 Ereignis(se) aus %2 können nicht in den Verlauf (%3). Sie wurden gesondert nach %4 verschoben; die übrigen Ereignisse der Datei werden gesendet.</translation>
    </message>
</context>
<context>
    <name>Toffee::StreamTransport</name>
    <message>
        <source> (framed)</source>
        <translation> (gerahmt)</translation>
    </message>
    <message>
        <source>%1 sent a line longer than %2 bytes; only its first %2 bytes were kept.</source>
        <translation>%1 hat eine Zeile mit mehr als %2 Bytes gesendet; nur ihre ersten %2 Bytes wurden behalten.</translation>
    </message>
    <message>
        <source>%1 is not open.</source>
        <translation>%1 ist nicht geöffnet.</translation>
    </message>
    <message>
        <source>%1 speaks Makera&apos;s frames (its firmware from 1.0.4 on), not the plain text chosen. Plain text would leave it deaf until it is restarted, so nothing more was sent. Choose automatic (--protocol auto, or leave it out) or framed.</source>
        <translation>%1 spricht Makeras Rahmen (seine Firmware ab 1.0.4), nicht den gewählten Klartext. Klartext würde sie bis zum Neustart taub machen, deshalb wurde nichts weiter gesendet. Wählen Sie automatisch (--protocol auto oder weglassen) oder Rahmen (framed).</translation>
    </message>
    <message>
        <source>%1 speaks plain text, not Makera&apos;s frames as chosen. Nothing more was sent. Choose automatic (--protocol auto, or leave it out) or text.</source>
        <translation>%1 spricht Klartext, nicht Makeras Rahmen wie gewählt. Nichts weiter wurde gesendet. Wählen Sie automatisch (--protocol auto oder weglassen) oder Klartext (text).</translation>
    </message>
    <message>
        <source>%1 did not answer within %2 s, in plain text or in Makera&apos;s frames. Check that the machine is switched on and has started, and the address or port.</source>
        <translation>%1 hat nicht innerhalb von %2 s geantwortet, weder im Klartext noch in Makeras Rahmen. Prüfen Sie, ob die Maschine eingeschaltet und gestartet ist, sowie die Adresse oder den Anschluss.</translation>
    </message>
</context>
<context>
    <name>Toffee::TableReading</name>
    <message>
        <source>tool %1 is already on line %2; tool numbers must be unique.</source>
        <translation>Werkzeug %1 steht schon in Zeile %2; Werkzeugnummern müssen eindeutig sein.</translation>
    </message>
</context>
<context>
    <name>Toffee::TcpTransport</name>
    <message>
        <source>&quot;%1&quot; is not a machine&apos;s address: give HOST or HOST:PORT (the port is %2 when not given), such as 192.168.1.57 or carvera.local:2222.</source>
        <translation>„%1“ ist keine Maschinenadresse: Geben Sie HOST oder HOST:PORT an (ohne Port gilt %2), etwa 192.168.1.57 oder carvera.local:2222.</translation>
    </message>
    <message>
        <source>%1 over the network</source>
        <translation>%1 über das Netzwerk</translation>
    </message>
    <message>
        <source>%1 did not answer within %2 s. Check that the machine is switched on and on this network, and its address (the machine&apos;s screen shows it).</source>
        <translation>%1 hat nicht innerhalb von %2 s geantwortet. Prüfen Sie, ob die Maschine eingeschaltet und in diesem Netzwerk ist, und ihre Adresse (der Bildschirm der Maschine zeigt sie).</translation>
    </message>
    <message>
        <source>Nothing answers at %1 (the connection was refused): the machine&apos;s Wi-Fi console is off, or the port is wrong (a Carvera listens on %2). Check the address and try again.</source>
        <translation>Unter %1 antwortet nichts (die Verbindung wurde abgewiesen): Die WLAN-Konsole der Maschine ist aus, oder der Port ist falsch (eine Carvera hört auf %2). Prüfen Sie die Adresse und versuchen Sie es erneut.</translation>
    </message>
    <message>
        <source>%1 is not a host name this computer can find. Give the machine&apos;s address as the machine&apos;s screen shows it (such as 192.168.1.57).</source>
        <translation>%1 ist kein Hostname, den dieser Computer finden kann. Geben Sie die Adresse der Maschine so an, wie ihr Bildschirm sie zeigt (etwa 192.168.1.57).</translation>
    </message>
    <message>
        <source>Cannot reach %1: %2. Check that this computer and the machine are on the same network.</source>
        <translation>%1 ist nicht erreichbar: %2. Prüfen Sie, ob dieser Computer und die Maschine im selben Netzwerk sind.</translation>
    </message>
    <message>
        <source>The machine at %1 closed the connection: it was switched off or restarted, or it serves another program now. Check the machine, then connect again.</source>
        <translation>Die Maschine unter %1 hat die Verbindung geschlossen: Sie wurde ausgeschaltet oder neu gestartet, oder sie bedient jetzt ein anderes Programm. Prüfen Sie die Maschine und verbinden Sie sich erneut.</translation>
    </message>
    <message>
        <source>The link to %1 was lost (%2): the machine was switched off or left the network. Check the machine, then connect again.</source>
        <translation>Die Verbindung zu %1 ist abgerissen (%2): Die Maschine wurde ausgeschaltet oder hat das Netzwerk verlassen. Prüfen Sie die Maschine und verbinden Sie sich erneut.</translation>
    </message>
</context>
<context>
    <name>Toffee::TloPanel</name>
    <message>
        <source>Machine state</source>
        <translation>Maschinenzustand</translation>
    </message>
    <message>
        <source>Active tool</source>
        <translation>Aktives Werkzeug</translation>
    </message>
    <message>
        <source>Reference tool MCS Z</source>
        <translation>Maschinen-Z des Referenzwerkzeugs</translation>
    </message>
    <message>
        <source>Current tool MCS Z</source>
        <translation>Maschinen-Z des aktuellen Werkzeugs</translation>
    </message>
    <message>
        <source>Tool length offset</source>
        <translation>Werkzeuglängenkorrektur</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>Entsperren</translation>
    </message>
    <message>
        <source>Unlock the machine</source>
        <translation>Maschine entsperren</translation>
    </message>
    <message>
        <source>Clear the halt ($X) — Ctrl+Shift+U</source>
        <translation>Den Halt aufheben ($X) — Strg+Umschalt+U</translation>
    </message>
    <message>
        <source>State:</source>
        <translation>Zustand:</translation>
    </message>
    <message>
        <source>TLO:</source>
        <translation>TLO:</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>Verbinde …</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>Nicht verbunden</translation>
    </message>
    <message>
        <source>Unlock failed</source>
        <translation>Entsperren fehlgeschlagen</translation>
    </message>
    <message>
        <source>Where the tool length offset came from</source>
        <translation>Woher die Werkzeuglängenkorrektur stammt</translation>
    </message>
    <message>
        <source>Why the machine halted and what to do</source>
        <translation>Warum die Maschine angehalten hat und was zu tun ist</translation>
    </message>
    <message>
        <source>Tool:</source>
        <translation>Werkzeug:</translation>
    </message>
    <message>
        <source>Reference Z:</source>
        <translation>Referenz-Z:</translation>
    </message>
    <message>
        <source>Current Z:</source>
        <translation>Aktuelles Z:</translation>
    </message>
    <message>
        <source>HALTED</source>
        <translation>ANGEHALTEN</translation>
    </message>
    <message>
        <source>Connected</source>
        <translation>Verbunden</translation>
    </message>
    <message>
        <source>Nothing that moves the machine or changes its offsets runs until then.</source>
        <translation>Bis dahin läuft nichts, was die Maschine bewegt oder ihre Korrekturen ändert.</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keins</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>nicht gemessen</translation>
    </message>
    <message>
        <source>T%1 has no TLO in the table</source>
        <translation>T%1 hat keine TLO in der Tabelle</translation>
    </message>
    <message>
        <source>not T%1&apos;s: the table holds %2</source>
        <translation>nicht die von T%1: Die Tabelle hat %2</translation>
    </message>
    <message>
        <source>set by hand %1, not measured</source>
        <translation>von Hand gesetzt am %1, nicht gemessen</translation>
    </message>
    <message>
        <source>measured %1</source>
        <translation>gemessen am %1</translation>
    </message>
    <message>
        <source>T%1 FAILED ITS BREAK TEST — %2</source>
        <translation>T%1 HAT DEN BRUCHTEST NICHT BESTANDEN — %2</translation>
    </message>
    <message>
        <source>The machine is still halted: check it, then try Unlock again.</source>
        <translation>Die Maschine ist noch angehalten: Prüfen Sie sie und versuchen Sie dann erneut Entsperren.</translation>
    </message>
    <message>
        <source>Idle</source>
        <translation>Bereit</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>Läuft</translation>
    </message>
    <message>
        <source>Held</source>
        <translation>Angehalten (Hold)</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Referenzfahrt</translation>
    </message>
    <message>
        <source>Asleep</source>
        <translation>Ruhezustand</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>Pausiert</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>Wartet</translation>
    </message>
    <message>
        <source>The machine reported an alarm.</source>
        <translation>Die Maschine hat einen Alarm gemeldet.</translation>
    </message>
    <message>
        <source>Check the machine, then Unlock ($X).</source>
        <translation>Prüfen Sie die Maschine, dann Entsperren ($X).</translation>
    </message>
    <message>
        <source>not reported</source>
        <translation>nicht gemeldet</translation>
    </message>
    <message>
        <source>the machine has no TLO in force: probe the tool first</source>
        <translation>Die Maschine hat keine gültige Längenkorrektur: Vermessen Sie zuerst das Werkzeug</translation>
    </message>
    <message>
        <source>The break test found %1 broken, and the machine halted with the length it measured in force (%2 above).
Check the tool, then Unlock: Toffee sets its stored TLO, %3, back first.</source>
        <translation>Die Bruchprüfung hat %1 als gebrochen befunden, und die Maschine hat mit der gemessenen Länge in Kraft angehalten (%2, oben).
Prüfen Sie das Werkzeug, dann Entsperren: Toffee setzt zuerst seine gespeicherte Längenkorrektur %3 zurück.</translation>
    </message>
    <message>
        <source>the tool</source>
        <translation>das Werkzeug</translation>
    </message>
    <message>
        <source>its TLO</source>
        <translation>seine Längenkorrektur</translation>
    </message>
    <message>
        <source>Unlock with T%1 marked broken?</source>
        <translation>Entsperren, obwohl T%1 als gebrochen markiert ist?</translation>
    </message>
    <message>
        <source>T%1 failed its break test: it may be broken, and the machine halted so that it cuts nothing more.</source>
        <translation>T%1 hat seinen Bruchtest nicht bestanden: Es könnte gebrochen sein, und die Maschine hat angehalten, damit es nichts mehr schneidet.</translation>
    </message>
    <message>
        <source>Look at the tool first, and replace it if it is broken. Unlock sets T%1&apos;s stored TLO, %2, back before anything can move; the mark stays until T%1 is measured again (Probe).</source>
        <translation>Sehen Sie sich zuerst das Werkzeug an und ersetzen Sie es, wenn es gebrochen ist. Entsperren setzt die gespeicherte Längenkorrektur von T%1, %2, zurück, bevor sich etwas bewegen kann; die Markierung bleibt, bis T%1 erneut gemessen wird (Messen).</translation>
    </message>
    <message>
        <source>Look at the tool first, and replace it if it is broken. The mark stays until T%1 is measured again (Probe).</source>
        <translation>Sehen Sie sich zuerst das Werkzeug an und ersetzen Sie es, wenn es gebrochen ist. Die Markierung bleibt, bis T%1 erneut gemessen wird (Messen).</translation>
    </message>
    <message>
        <source>no status report yet</source>
        <translation>noch kein Statusbericht</translation>
    </message>
    <message>
        <source>no status report for %1 s</source>
        <translation>seit %1 s kein Statusbericht</translation>
    </message>
    <message>
        <source>HALTED (%1; it stays halted until unlocked)</source>
        <translation>ANGEHALTEN (%1; bleibt angehalten bis zum Entsperren)</translation>
    </message>
    <message>
        <source>%1 (stale: %2)</source>
        <translation>%1 (veraltet: %2)</translation>
    </message>
    <message>
        <source>Waiting for the operator</source>
        <translation>Wartet auf den Bediener</translation>
    </message>
    <message>
        <source>The machine said: “%1”</source>
        <translation>Die Maschine meldete: „%1“</translation>
    </message>
    <message>
        <source>Look at the tool first, and replace it if it is broken. Unlock sets T%1&apos;s stored TLO, %2, back before anything can move: it was set by hand, not measured, and the break test measured %3. Probe T%1 before it cuts; the mark stays until then.</source>
        <translation>Sehen Sie sich zuerst das Werkzeug an und ersetzen Sie es, wenn es gebrochen ist. Entsperren setzt die gespeicherte TL von T%1, %2, zurück, bevor sich etwas bewegen kann: Sie wurde von Hand gesetzt, nicht gemessen, und der Bruchtest maß %3. Vermessen Sie T%1, bevor es schneidet; bis dahin bleibt die Markierung.</translation>
    </message>
    <message>
        <source>another length</source>
        <translation>eine andere Länge</translation>
    </message>
    <message>
        <source>&amp;Unlock</source>
        <comment>the strip&apos;s button</comment>
        <translation>&amp;Entsperren</translation>
    </message>
    <message>
        <source>as the table&apos;s, measured %1</source>
        <translation>wie in der Tabelle, gemessen %1</translation>
    </message>
    <message>
        <source>read from the controller %1, not measured</source>
        <translation>%1 aus der Steuerung gelesen, nicht gemessen</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolChangeWait</name>
    <message>
        <source>Put T%1 in the Spindle</source>
        <translation>T%1 in die Spindel einsetzen</translation>
    </message>
    <message>
        <source>The machine waits for T%1. Put it in the spindle, then press cycle start on the machine or Continue here; it is then measured.</source>
        <translation>Die Maschine wartet auf T%1. Setzen Sie es in die Spindel ein und drücken Sie dann Zyklusstart an der Maschine oder hier Weiter; danach wird es gemessen.</translation>
    </message>
    <message>
        <source>The machine waits for T%1. Put it in the spindle, then press the machine&apos;s button; it is then measured.</source>
        <translation>Die Maschine wartet auf T%1. Setzen Sie es in die Spindel ein und drücken Sie dann die Taste der Maschine; danach wird es gemessen.</translation>
    </message>
    <message>
        <source>The change waits up to %1 min; End the Change stops it on the machine and records nothing.</source>
        <translation>Der Wechsel wartet bis zu %1 min; Wechsel beenden stoppt ihn an der Maschine und zeichnet nichts auf.</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>Weiter</translation>
    </message>
    <message>
        <source>End the Change</source>
        <translation>Wechsel beenden</translation>
    </message>
    <message>
        <source>The operator ended the change in the window.</source>
        <translation>Der Bediener hat den Wechsel im Fenster beendet.</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolContextMenu</name>
    <message>
        <source>Make &amp;Active (No Probe)…</source>
        <translation>&amp;Aktiv machen (ohne Vermessen)…</translation>
    </message>
    <message>
        <source>&amp;Set Its TLO…</source>
        <translation>&amp;TL setzen…</translation>
    </message>
    <message>
        <source>Make T%1 &amp;Active (No Probe)…</source>
        <translation>T%1 &amp;aktiv machen (ohne Vermessen)…</translation>
    </message>
    <message>
        <source>Connect to a machine that is idle and not halted first.</source>
        <translation>Verbinden Sie zuerst mit einer Maschine, die bereit und nicht angehalten ist.</translation>
    </message>
    <message>
        <source>Select one tool of the table.</source>
        <translation>Wählen Sie ein Werkzeug der Tabelle.</translation>
    </message>
    <message>
        <source>T%1 is already the active tool.</source>
        <translation>T%1 ist bereits das aktive Werkzeug.</translation>
    </message>
    <message>
        <source>Tell the machine that T%1 is in the spindle, without probing it.</source>
        <translation>Der Maschine sagen, dass T%1 in der Spindel ist, ohne es zu vermessen.</translation>
    </message>
    <message>
        <source>&amp;Set T%1&apos;s TLO…</source>
        <translation>TL von T%1 &amp;setzen…</translation>
    </message>
    <message>
        <source>Set the TLO of the tool in the spindle by hand (Machine ▸ Set the offset by hand).</source>
        <translation>Die TL des Werkzeugs in der Spindel von Hand setzen (Maschine ▸ Korrektur von Hand setzen).</translation>
    </message>
    <message>
        <source>Only the tool in the spindle&apos;s TLO can be set: make T%1 active first.</source>
        <translation>Nur die TL des Werkzeugs in der Spindel lässt sich setzen: Machen Sie T%1 zuerst aktiv.</translation>
    </message>
    <message>
        <source>&amp;Restore T%1&apos;s Known TLO…</source>
        <translation>Bekannte TL von T%1 &amp;wiederherstellen…</translation>
    </message>
    <message>
        <source>&amp;Restore Known TLO…</source>
        <translation>Bekannte TL &amp;wiederherstellen…</translation>
    </message>
    <message>
        <source>&amp;Probe T%1 (in the Spindle)</source>
        <translation>T%1 &amp;vermessen (in der Spindel)</translation>
    </message>
    <message>
        <source>&amp;Probe the Tool in the Spindle</source>
        <translation>Werkzeug in der Spindel &amp;vermessen</translation>
    </message>
    <message>
        <source>Make T%1 active?</source>
        <translation>T%1 aktiv machen?</translation>
    </message>
    <message>
        <source>Is T%1 in the spindle now?</source>
        <translation>Ist T%1 jetzt in der Spindel?</translation>
    </message>
    <message>
        <source>The machine takes T%1 as the tool in the spindle, without probing it. It keeps the TLO in force now (another tool&apos;s, or none): probe T%1 or restore its TLO before it cuts.

Sends: %2</source>
        <translation>Die Maschine nimmt T%1 als Werkzeug in der Spindel, ohne es zu vermessen. Sie behält die jetzt wirksame TL (die eines anderen Werkzeugs oder keine): Vermessen Sie T%1 oder stellen Sie seine TL wieder her, bevor es schneidet.

Sendet: %2</translation>
    </message>
    <message>
        <source>T%1 Is in the Spindle</source>
        <translation>T%1 ist in der Spindel</translation>
    </message>
    <message>
        <source>T%1 was not made active</source>
        <translation>T%1 wurde nicht aktiv gemacht</translation>
    </message>
    <message>
        <source>The machine&apos;s tool is as it was.</source>
        <translation>Das Werkzeug der Maschine ist unverändert.</translation>
    </message>
    <message>
        <source>&amp;Change to It (M6)…</source>
        <translation>&amp;Wechseln zu diesem (M6)…</translation>
    </message>
    <message>
        <source>&amp;Change to T%1 (M6)…</source>
        <translation>&amp;Wechseln zu T%1 (M6)…</translation>
    </message>
    <message>
        <source>The machine&apos;s tool change to T%1, then T%1 measured on the tool setter.</source>
        <translation>Werkzeugwechsel der Maschine zu T%1, danach wird T%1 am Werkzeugtaster gemessen.</translation>
    </message>
    <message>
        <source>The machine puts the tool in the spindle back, takes T%1 from its rack (or asks you for it when it is not in the rack) and measures it on the tool setter. Keep hands clear.</source>
        <translation>Die Maschine legt das Werkzeug in der Spindel zurück, nimmt T%1 aus dem Magazin (oder fragt Sie danach, wenn es nicht im Magazin ist) und misst es am Werkzeugtaster. Hände weg.</translation>
    </message>
    <message>
        <source>The machine stops and waits for you to put T%1 in the spindle; press cycle start on the machine (or Continue here), and T%1 is measured on the tool setter. Keep hands clear.</source>
        <translation>Die Maschine hält an und wartet, bis Sie T%1 in die Spindel setzen; drücken Sie Zyklusstart an der Maschine (oder hier Fortsetzen), dann wird T%1 am Werkzeugtaster gemessen. Hände weg.</translation>
    </message>
    <message>
        <source>Change to T%1?</source>
        <translation>Zu T%1 wechseln?</translation>
    </message>
    <message>
        <source>Change to T%1 now?</source>
        <translation>Jetzt zu T%1 wechseln?</translation>
    </message>
    <message>
        <source>Sends: M6 T%1</source>
        <translation>Sendet: M6 T%1</translation>
    </message>
    <message>
        <source>Change to T%1</source>
        <translation>Zu T%1 wechseln</translation>
    </message>
    <message>
        <source>The change to T%1 did not finish</source>
        <translation>Der Wechsel zu T%1 wurde nicht beendet</translation>
    </message>
    <message>
        <source>Nothing was written to the tool table.</source>
        <translation>In die Werkzeugtabelle wurde nichts geschrieben.</translation>
    </message>
    <message>
        <source>T%1 is in the spindle, measured: TLO %2, recorded in the table.</source>
        <translation>T%1 ist in der Spindel, gemessen: TLO %2, in der Tabelle erfasst.</translation>
    </message>
    <message>
        <source>T%1 was not recorded</source>
        <translation>T%1 wurde nicht erfasst</translation>
    </message>
    <message>
        <source>T%1 is in the spindle, but its TLO could not be recorded: %2</source>
        <translation>T%1 ist in der Spindel, aber seine TLO konnte nicht erfasst werden: %2</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolDocument</name>
    <message>
        <source>This table has no file yet; use Save As.</source>
        <translation>Diese Tabelle hat noch keine Datei; verwenden Sie „Speichern unter“.</translation>
    </message>
    <message>
        <source>%1 is in %2 but this table is in %3; Toffee does not convert units on import.</source>
        <translation>%1 ist in %2, diese Tabelle aber in %3; Toffee rechnet beim Import keine Einheiten um.</translation>
    </message>
    <message>
        <source>Import %1 tools</source>
        <translation>%1 Werkzeuge importieren</translation>
    </message>
    <message>
        <source>Measure T%1</source>
        <translation>T%1 vermessen</translation>
    </message>
    <message>
        <source>%1 no longer exists; saving writes it again.</source>
        <translation>%1 existiert nicht mehr; Speichern schreibt die Datei neu.</translation>
    </message>
    <message>
        <source>%1 does not load (%2), so the recovered edits are a new table: save them with Save As.</source>
        <translation>%1 lässt sich nicht laden (%2), daher sind die wiederhergestellten Änderungen eine neue Tabelle: Speichern Sie sie mit „Speichern unter“.</translation>
    </message>
    <message>
        <source>Recover unsaved edits</source>
        <translation>Ungesicherte Änderungen wiederherstellen</translation>
    </message>
    <message>
        <source>Keep only what %1 holds</source>
        <translation>Nur behalten, was %1 enthält</translation>
    </message>
    <message>
        <source>Set T%1 TLO by hand</source>
        <translation>TLO von T%1 von Hand setzen</translation>
    </message>
    <message>
        <source>Mark T%1 failed its break test</source>
        <translation>T%1 als im Bruchtest durchgefallen markieren</translation>
    </message>
    <message>
        <source>T%1 passed its break test</source>
        <translation>T%1 hat den Bruchtest bestanden</translation>
    </message>
    <message>
        <source>Update from the library</source>
        <translation>Aus der Bibliothek aktualisieren</translation>
    </message>
    <message>
        <source>Take T%1 from %2</source>
        <translation>T%1 von %2 übernehmen</translation>
    </message>
    <message>
        <source>New cutter in T%1</source>
        <translation>Neuer Fräser in T%1</translation>
    </message>
    <message>
        <source>Pull T%1&apos;s TLO from the controller</source>
        <translation>TLO von T%1 aus der Steuerung holen</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolLife</name>
    <message>
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <source>%1 uses</source>
        <translation>%1 Einsätze</translation>
    </message>
    <message>
        <source>Type the tool&apos;s life as minutes of cutting, uses (programs), or both: &quot;90 min&quot;, &quot;40 uses&quot;, &quot;90 min, 40 uses&quot;; leave it empty for no limit.</source>
        <translation>Geben Sie die Standzeit als Zerspanminuten, Einsätze (Programme) oder beides ein: „90 min“, „40 Einsätze“, „90 min, 40 Einsätze“; leer lassen für keine Grenze.</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>uses</source>
        <translation>Einsätze</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a tool life. %2</source>
        <translation>„%1“ ist keine Standzeit. %2</translation>
    </message>
    <message>
        <source>%1 of %2 min</source>
        <translation>%1 von %2 min</translation>
    </message>
    <message>
        <source>%1 of %2 uses</source>
        <translation>%1 von %2 Einsätzen</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolSetter</name>
    <message>
        <source>The tool setter &quot;%1&quot; is not X,Y,ZMIN (machine coordinates in mm, e.g. 0,0,-120) nor X,Y,ZMIN,SEEK,LATCH[,BACKOFF] (feeds in mm/min, back-off in mm).</source>
        <translation>Der Werkzeugtaster „%1“ ist weder X,Y,ZMIN (Maschinenkoordinaten in mm, z. B. 0,0,-120) noch X,Y,ZMIN,SEEK,LATCH[,BACKOFF] (Vorschübe in mm/min, Rückzug in mm).</translation>
    </message>
    <message>
        <source>The tool setter &quot;%1&quot;: &quot;%2&quot; is not a number.</source>
        <translation>Werkzeugtaster „%1“: „%2“ ist keine Zahl.</translation>
    </message>
    <message>
        <source>The tool setter&apos;s position must be machine coordinates from -%1 to %1 mm.</source>
        <translation>Die Position des Werkzeugtasters muss in Maschinenkoordinaten zwischen -%1 und %1 mm liegen.</translation>
    </message>
    <message>
        <source>The tool setter&apos;s lowest Z (%1 mm) must be below the Z it lifts to (%2 mm): the search goes down.</source>
        <translation>Das tiefste Z des Werkzeugtasters (%1 mm) muss unter dem Z liegen, auf das hochgefahren wird (%2 mm): Die Suche geht nach unten.</translation>
    </message>
    <message>
        <source>A probing feed must be more than 0 and at most %1 mm/min.</source>
        <translation>Ein Messvorschub muss größer als 0 und höchstens %1 mm/min sein.</translation>
    </message>
    <message>
        <source>The latch feed (%1 mm/min) must not be faster than the search feed (%2 mm/min): the second touch is the slow, precise one.</source>
        <translation>Der Feinvorschub (%1 mm/min) darf nicht schneller sein als der Suchvorschub (%2 mm/min): Die zweite Berührung ist die langsame, genaue.</translation>
    </message>
    <message>
        <source>The back-off between the two touches must be more than 0 and at most %1 mm.</source>
        <translation>Der Rückzug zwischen den beiden Berührungen muss größer als 0 und höchstens %1 mm sein.</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolSetterDialog</name>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source> mm/min</source>
        <translation> mm/min</translation>
    </message>
    <message>
        <source>Tool Setter of %1</source>
        <translation>Werkzeugtaster von %1</translation>
    </message>
    <message>
        <source>Where the tool setter is, in machine coordinates, and how Toffee touches it: it lifts to the safe Z, moves over the setter, searches down to the lowest Z at the search feed, backs off, and touches again at the latch feed.</source>
        <translation>Wo der Werkzeugtaster in Maschinenkoordinaten liegt und wie Toffee ihn antastet: Die Maschine fährt auf das sichere Z hoch, fährt über den Taster, sucht mit dem Suchvorschub abwärts bis zum tiefsten Z, fährt zurück und tastet mit dem Feinvorschub erneut an.</translation>
    </message>
    <message>
        <source>Setter &amp;X:</source>
        <translation>Taster &amp;X:</translation>
    </message>
    <message>
        <source>Setter &amp;Y:</source>
        <translation>Taster &amp;Y:</translation>
    </message>
    <message>
        <source>&amp;Lowest Z to search to:</source>
        <translation>&amp;Tiefstes Z für die Suche:</translation>
    </message>
    <message>
        <source>Safe Z to &amp;lift to:</source>
        <translation>Sicheres Z zum &amp;Hochfahren:</translation>
    </message>
    <message>
        <source>&amp;Search feed:</source>
        <translation>&amp;Suchvorschub:</translation>
    </message>
    <message>
        <source>L&amp;atch feed:</source>
        <translation>&amp;Feinvorschub:</translation>
    </message>
    <message>
        <source>&amp;Back-off between touches:</source>
        <translation>&amp;Rückzug zwischen den Berührungen:</translation>
    </message>
    <message>
        <source>From the machine</source>
        <translation>Von der Maschine</translation>
    </message>
    <message>
        <source>Jog the spindle over the setter&apos;s centre, then take its X and Y from where the machine stands.</source>
        <translation>Fahren Sie die Spindel im Tippbetrieb über die Mitte des Tasters und übernehmen Sie dann X und Y von der Maschinenposition.</translation>
    </message>
    <message>
        <source>Where the machine stands: waiting for its report…</source>
        <translation>Position der Maschine: warte auf ihre Meldung …</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>Jog s&amp;tep:</source>
        <translation>Sc&amp;hrittweite:</translation>
    </message>
    <message>
        <source>Y+</source>
        <translation>Y+</translation>
    </message>
    <message>
        <source>X−</source>
        <translation>X−</translation>
    </message>
    <message>
        <source>X+</source>
        <translation>X+</translation>
    </message>
    <message>
        <source>Y−</source>
        <translation>Y−</translation>
    </message>
    <message>
        <source>Z+</source>
        <translation>Z+</translation>
    </message>
    <message>
        <source>Z−</source>
        <translation>Z−</translation>
    </message>
    <message>
        <source>Moves the machine by the jog step along %1.</source>
        <translation>Bewegt die Maschine um die Schrittweite in %1.</translation>
    </message>
    <message>
        <source>Sto&amp;p</source>
        <translation>Sto&amp;pp</translation>
    </message>
    <message>
        <source>&amp;Use X and Y Where It Stands</source>
        <translation>X und Y der Maschinenposition &amp;übernehmen</translation>
    </message>
    <message>
        <source>Where the machine stands: X %1, Y %2, Z %3 mm (machine coordinates).</source>
        <translation>Position der Maschine: X %1, Y %2, Z %3 mm (Maschinenkoordinaten).</translation>
    </message>
    <message>
        <source>Jog the machine?</source>
        <translation>Maschine im Tippbetrieb verfahren?</translation>
    </message>
    <message>
        <source>The machine moves each time you press a jog button.</source>
        <translation>Die Maschine bewegt sich bei jedem Druck auf eine Tipptaste.</translation>
    </message>
    <message>
        <source>Jog</source>
        <translation>Verfahren</translation>
    </message>
    <message>
        <source>The setter&apos;s X and Y are where the machine stands: X %1, Y %2 mm.</source>
        <translation>X und Y des Tasters sind die Maschinenposition: X %1, Y %2 mm.</translation>
    </message>
    <message>
        <source>Stops the jog at once where the machine stands.</source>
        <translation>Hält das Verfahren sofort dort an, wo die Maschine steht.</translation>
    </message>
    <message>
        <source>Each press moves it by the jog step, at %1 mm/min, and Stop stops it. Keep hands clear.</source>
        <translation>Jeder Druck verfährt sie um die Schrittweite, mit %1 mm/min, und Stopp hält sie an. Hände weg von der Maschine.</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolTable</name>
    <message>
        <source>there is no tool %1 in the table.</source>
        <translation>Es gibt kein Werkzeug %1 in der Tabelle.</translation>
    </message>
    <message>
        <source>T%1 is not in the table.</source>
        <translation>T%1 ist nicht in der Tabelle.</translation>
    </message>
    <message>
        <source>T%1: %2 Nothing was recorded.</source>
        <translation>T%1: %2 Nichts wurde aufgezeichnet.</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolTableModel</name>
    <message>
        <source>Tool</source>
        <translation>Werkzeug</translation>
    </message>
    <message>
        <source>Pocket</source>
        <translation>Platz</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>Beschreibung</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>Länge</translation>
    </message>
    <message>
        <source>Length wear</source>
        <translation>Längenverschleiß</translation>
    </message>
    <message>
        <source>Total length</source>
        <translation>Gesamtlänge</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Radius</translation>
    </message>
    <message>
        <source>Radius wear</source>
        <translation>Radiusverschleiß</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>Notizen</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number; enter a value such as -12.345.</source>
        <translation>%1: „%2“ ist keine Zahl; geben Sie einen Wert wie -12,345 ein.</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a whole number.</source>
        <translation>%1: „%2“ ist keine ganze Zahl.</translation>
    </message>
    <message>
        <source>this column cannot be edited.</source>
        <translation>Diese Spalte lässt sich nicht bearbeiten.</translation>
    </message>
    <message>
        <source>tool number %1 is already in the table; tool numbers must be unique.</source>
        <translation>Werkzeugnummer %1 ist schon in der Tabelle; Werkzeugnummern müssen eindeutig sein.</translation>
    </message>
    <message>
        <source>Pocket %1 also holds %2. LinuxCNC&apos;s random tool changer needs each tool in its own pocket.</source>
        <translation>Platz %1 enthält auch %2. Der zufällige Werkzeugwechsler (random tool changer) von LinuxCNC braucht für jedes Werkzeug einen eigenen Platz.</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>nicht gemessen</translation>
    </message>
    <message>
        <source>%1 (by hand)</source>
        <translation>%1 (von Hand)</translation>
    </message>
    <message>
        <source>%1 — BROKEN?</source>
        <translation>%1 — GEBROCHEN?</translation>
    </message>
    <message>
        <source>T%1 has not been measured on the tool setter.</source>
        <translation>T%1 wurde nicht am Werkzeugtaster gemessen.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was set on the machine by hand, not measured. A break test compares against it.</source>
        <translation>Die TLO %2 von T%1 wurde an der Maschine von Hand gesetzt, nicht gemessen. Ein Bruchtest vergleicht mit diesem Wert.</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was measured on the tool setter.</source>
        <translation>Die TLO %2 von T%1 wurde am Werkzeugtaster gemessen.</translation>
    </message>
    <message>
        <source>T%1 failed its last break test: check it, replace it if it is damaged, then probe it again. It stays marked until it is probed.</source>
        <translation>T%1 hat seinen letzten Bruchtest nicht bestanden: Prüfen Sie es, ersetzen Sie es, wenn es beschädigt ist, und vermessen Sie es dann erneut. Es bleibt markiert, bis es vermessen wird.</translation>
    </message>
    <message>
        <source>%1 (stale)</source>
        <translation>%1 (veraltet)</translation>
    </message>
    <message>
        <source>The tool length offset: measured on the tool setter, or set by hand (marked &quot;by hand&quot;).</source>
        <translation>Die Werkzeuglängenkorrektur: am Werkzeuglängensensor gemessen oder von Hand gesetzt (markiert mit „von Hand“).</translation>
    </message>
    <message>
        <source>When the TLO was measured or set.</source>
        <translation>Wann die TLO gemessen oder gesetzt wurde.</translation>
    </message>
    <message>
        <source>TLO</source>
        <translation>TLO</translation>
    </message>
    <message>
        <source>TLO recorded</source>
        <translation>TLO erfasst</translation>
    </message>
    <message>
        <source>T%1&apos;s cutter has cut %2 in %3 recorded program runs since it went in.</source>
        <translation>Der Fräser von T%1 hat seit dem Einsetzen %2 in %3 aufgezeichneten Programmläufen zerspant.</translation>
    </message>
    <message>
        <source>It has no life limit: type one here, as &quot;90 min&quot;, &quot;40 uses&quot; or both.</source>
        <translation>Es hat keine Standzeit: Geben Sie hier eine ein, etwa „90 min“, „40 Einsätze“ oder beides.</translation>
    </message>
    <message>
        <source>Its life limit is %1.</source>
        <translation>Seine Standzeit ist %1.</translation>
    </message>
    <message>
        <source>It is past its limit: put in a new cutter (Edit ▸ New Cutter…).</source>
        <translation>Die Standzeit ist überschritten: Setzen Sie einen neuen Fräser ein (Bearbeiten ▸ Neuer Fräser …).</translation>
    </message>
    <message>
        <source>It is near its limit: have a new cutter ready.</source>
        <translation>Die Standzeit ist fast erreicht: Halten Sie einen neuen Fräser bereit.</translation>
    </message>
    <message>
        <source>Tool life</source>
        <translation>Standzeit</translation>
    </message>
    <message>
        <source>%1 (pulled)</source>
        <translation>%1 (aus Steuerung)</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was read from the controller&apos;s own table (Pull Offsets), not measured by Toffee. A break test compares against it.</source>
        <translation>Die TLO %2 von T%1 wurde aus der eigenen Tabelle der Steuerung gelesen (Korrekturen von der Steuerung übernehmen), nicht von Toffee gemessen. Ein Bruchtest vergleicht mit ihr.</translation>
    </message>
    <message>
        <source>Probing</source>
        <translation>Antasten</translation>
    </message>
    <message>
        <source>T%1 is touched once at the setter&apos;s centre. Type &quot;X 20, 4 edges, spread 0.03&quot; for a face mill touched on each edge, off-centre.</source>
        <translation>T%1 wird einmal in der Mitte des Längenmessgeräts angetastet. Geben Sie „X 20, 4 Schneiden, Streuung 0.03“ ein für einen Planfräser, der außermittig an jeder Schneide angetastet wird.</translation>
    </message>
    <message>
        <source>T%1 is probed so: %2.</source>
        <translation>T%1 wird so angetastet: %2.</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolTablePanel</name>
    <message>
        <source>Filter tools</source>
        <translation>Werkzeuge filtern</translation>
    </message>
    <message>
        <source>Filter tools (number, description, notes…)</source>
        <translation>Werkzeuge filtern (Nummer, Beschreibung, Notizen …)</translation>
    </message>
    <message>
        <source>Tool table</source>
        <translation>Werkzeugtabelle</translation>
    </message>
    <message>
        <source>Read-only</source>
        <translation>Schreibgeschützt</translation>
    </message>
</context>
<context>
    <name>Toffee::WearTrend</name>
    <message>
        <source>T%1 measured %2 shorter than its trend predicts (±%3): check the tip.</source>
        <translation>T%1 hat %2 kürzer gemessen, als sein Trend vorhersagt (±%3): Prüfen Sie die Spitze.</translation>
    </message>
    <message>
        <source>T%1 measured %2 longer than its trend predicts (±%3): check that it sits right in its holder.</source>
        <translation>T%1 hat %2 länger gemessen, als sein Trend vorhersagt (±%3): Prüfen Sie, ob es richtig im Halter sitzt.</translation>
    </message>
</context>
<context>
    <name>Toffee::XmlText</name>
    <message>
        <source>this is not an HSM tool library Toffee reads: it has a document type declaration (&lt;!DOCTYPE&gt;), which no HSM library has and whose declarations can make reading take hours.</source>
        <translation>das ist keine HSM-Werkzeugbibliothek, die Toffee liest: sie hat eine Dokumenttyp-Deklaration (&lt;!DOCTYPE&gt;), die keine HSM-Bibliothek hat und deren Deklarationen das Lesen stundenlang dauern lassen können.</translation>
    </message>
    <message>
        <source>this is not an HSM tool library Toffee reads: &lt;%1&gt; has more than %2 attributes; an element of an HSM library has a few dozen at most.</source>
        <translation>das ist keine HSM-Werkzeugbibliothek, die Toffee liest: &lt;%1&gt; hat mehr als %2 Attribute; ein Element einer HSM-Bibliothek hat höchstens einige Dutzend.</translation>
    </message>
    <message>
        <source>this is not an HSM tool library Toffee reads: &lt;%1&gt; brings the XML namespaces declared to %2; an HSM library declares one, and Toffee reads up to %3.</source>
        <translation>das ist keine HSM-Werkzeugbibliothek, die Toffee liest: mit &lt;%1&gt; sind %2 XML-Namensräume deklariert; eine HSM-Bibliothek deklariert einen, und Toffee liest bis zu %3.</translation>
    </message>
    <message>
        <source>this is not an HSM tool library Toffee reads: &lt;%1&gt; is nested %2 elements deep; an HSM library nests a few, and Toffee reads up to %3.</source>
        <translation>das ist keine HSM-Werkzeugbibliothek, die Toffee liest: &lt;%1&gt; ist %2 Elemente tief verschachtelt; eine HSM-Bibliothek verschachtelt wenige, und Toffee liest bis zu %3.</translation>
    </message>
    <message>
        <source>this is not an HSM tool library Toffee reads: it is in &quot;%1&quot;, an encoding Toffee does not know; save it as UTF-16 or UTF-8.</source>
        <translation>das ist keine HSM-Werkzeugbibliothek, die Toffee liest: sie ist in „%1“ kodiert, einer Kodierung, die Toffee nicht kennt; speichern Sie sie als UTF-16 oder UTF-8.</translation>
    </message>
    <message>
        <source>this is not well-formed XML: it is not valid %1 text.</source>
        <translation>das ist kein wohlgeformtes XML: es ist kein gültiger %1-Text.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Toffee, the tool offset manager.</source>
        <translation>Toffee, die Verwaltung für Werkzeugkorrekturen.</translation>
    </message>
    <message>
        <source>Connect to the machine on PORT.</source>
        <translation>Mit der Maschine an PORT verbinden.</translation>
    </message>
    <message>
        <source>Baud rate (default 115200).</source>
        <translation>Baudrate (Standard 115200).</translation>
    </message>
    <message>
        <source>Open the window, connect to the emulator, load the example table, probe, render once, and exit (0 when all went well).</source>
        <translation>Fenster öffnen, mit dem Emulator verbinden, die Beispieltabelle laden, vermessen, einmal zeichnen und beenden (0, wenn alles geklappt hat).</translation>
    </message>
    <message>
        <source>Use the dark palette.</source>
        <translation>Dunkle Farben verwenden.</translation>
    </message>
    <message>
        <source>Language: de, zh_CN or en (default: the system&apos;s).</source>
        <translation>Sprache: de, zh_CN oder en (Standard: die des Systems).</translation>
    </message>
    <message>
        <source>A tool table to open.</source>
        <translation>Eine Werkzeugtabelle zum Öffnen.</translation>
    </message>
    <message>
        <source>Check the G-code PROGRAM against the table once the window is open.</source>
        <translation>Das G-Code-Programm PROGRAM gegen die Tabelle prüfen, sobald das Fenster offen ist.</translation>
    </message>
    <message>
        <source>Connect to the built-in emulator, which takes a real machine&apos;s time for a tool change and a probe.</source>
        <translation>Mit dem eingebauten Emulator verbinden, der für einen Werkzeugwechsel und eine Messung so lange braucht wie eine echte Maschine.</translation>
    </message>
    <message>
        <source>The firmware the built-in emulator plays: community (default) or stock.</source>
        <translation>Die Firmware, die der eingebaute Emulator nachbildet: community (Standard) oder stock.</translation>
    </message>
    <message>
        <source>The history library: an SQLite file (or sqlite:PATH), or a shared one on PostgreSQL (postgresql://user@host:port/dbname; the password in ~/.pgpass).</source>
        <translation>Die Verlaufsbibliothek: eine SQLite-Datei (oder sqlite:PFAD) oder eine gemeinsame auf PostgreSQL (postgresql://user@host:port/dbname; das Passwort in ~/.pgpass).</translation>
    </message>
    <message>
        <source>Connect to the machine over Wi-Fi at HOST[:PORT] (port 2222 by default).</source>
        <translation>Über WLAN mit der Maschine unter HOST[:PORT] verbinden (standardmäßig Port 2222).</translation>
    </message>
</context>
</TS>
