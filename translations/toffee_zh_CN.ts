<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>BrokenTool</name>
    <message>
        <source>T%1 is marked broken: it failed its break test. Probing measures it as it is now, records that TLO and clears the mark: replace the tool first if it is broken.</source>
        <translation>T%1 被标记为断刀：它未通过断刀检测。测量会按其当前状态测量、记录该刀长补偿并清除标记：如果刀具已断，请先更换。</translation>
    </message>
    <message>
        <source>T%1 is marked broken: it failed its break test. A TLO set by hand does not clear the mark; measure the tool (Probe) once it is checked or replaced.</source>
        <translation>T%1 被标记为断刀：它未通过断刀检测。手动设置的刀长补偿不会清除标记；请在检查或更换刀具后测量（测量）。</translation>
    </message>
    <message>
        <source>T%1 is marked broken: it failed its last break test. Testing it again compares it with its stored TLO; a pass clears the mark.</source>
        <translation>T%1 被标记为断刀：它未通过上次断刀检测。再次检测会与其已存的刀长补偿比较；通过即清除标记。</translation>
    </message>
</context>
<context>
    <name>Toffee</name>
    <message>
        <source>tool number %1 is out of range; use %2 to %3.</source>
        <translation>刀具号 %1 超出范围；请使用 %2 到 %3。</translation>
    </message>
    <message>
        <source>pocket %1 is out of range; use %2 to %3.</source>
        <translation>刀位 %1 超出范围；请使用 %2 到 %3。</translation>
    </message>
    <message>
        <source>%1 is not a number; enter a value from %2 to %3 %4.</source>
        <translation>%1 不是数字；请输入 %2 到 %3 %4 之间的值。</translation>
    </message>
    <message>
        <source>%1 %2 %3 is out of range; a controller takes %4 to %5 %3.</source>
        <translation>%1 %2 %3 超出范围；控制器接受 %4 到 %5 %3。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a LinuxCNC tool field (X, Y, A, B, C, U, V, W, I, J or Q0-Q9).</source>
        <translation>“%1”不是 LinuxCNC 刀具字段（X、Y、A、B、C、U、V、W、I、J 或 Q0-Q9）。</translation>
    </message>
    <message>
        <source>the description is %1 characters long; keep it to %2.</source>
        <translation>描述长 %1 个字符；请不超过 %2 个。</translation>
    </message>
    <message>
        <source>the description must be one line of text, without tabs or line breaks.</source>
        <translation>描述必须是一行文字，不能有制表符或换行。</translation>
    </message>
    <message>
        <source>the notes are %1 characters long; keep them to %2.</source>
        <translation>备注长 %1 个字符；请不超过 %2 个。</translation>
    </message>
    <message>
        <source>length geometry</source>
        <translation>长度几何值</translation>
    </message>
    <message>
        <source>length wear</source>
        <translation>长度磨损</translation>
    </message>
    <message>
        <source>radius geometry</source>
        <translation>半径几何值</translation>
    </message>
    <message>
        <source>radius wear</source>
        <translation>半径磨损</translation>
    </message>
    <message>
        <source>measured TLO</source>
        <translation>测得的刀长补偿</translation>
    </message>
    <message>
        <source>tool number %1 is already in the table; tool numbers must be unique.</source>
        <translation>刀具号 %1 已在表中；刀具号必须唯一。</translation>
    </message>
    <message>
        <source>Toffee tool table (JSON)</source>
        <translation>Toffee 刀具表（JSON）</translation>
    </message>
    <message>
        <source>LinuxCNC tool table</source>
        <translation>LinuxCNC 刀具表</translation>
    </message>
    <message>
        <source>CSV spreadsheet</source>
        <translation>CSV 电子表格</translation>
    </message>
    <message>
        <source>unknown table format.</source>
        <translation>未知的表格格式。</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no wear columns: wear is added into the length and diameter.</source>
        <translation>LinuxCNC 刀具表没有磨损列：磨损会计入长度和直径。</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no place for measured TLOs: they are not saved.</source>
        <translation>LinuxCNC 刀具表无法存放测得的刀长补偿：它们不会被保存。</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no place for notes: they are not saved.</source>
        <translation>LinuxCNC 刀具表无法存放备注：它们不会被保存。</translation>
    </message>
    <message>
        <source>A LinuxCNC table does not record its units: the numbers are written in inches.</source>
        <translation>LinuxCNC 刀具表不记录单位：数字以英寸写入。</translation>
    </message>
    <message>
        <source>%1: unknown file type; use a .json, .tbl or .csv file.</source>
        <translation>%1：未知的文件类型；请使用 .json、.tbl 或 .csv 文件。</translation>
    </message>
    <message>
        <source>%1: cannot open: %2</source>
        <translation>%1：无法打开：%2</translation>
    </message>
    <message>
        <source>%1: cannot read: %2</source>
        <translation>%1：无法读取：%2</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a whole number.</source>
        <translation>“%1”必须是整数。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be a number.</source>
        <translation>“%1”必须是数字。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be text.</source>
        <translation>“%1”必须是文本。</translation>
    </message>
    <message>
        <source>each entry of &quot;tools&quot; must be a JSON object such as {&quot;number&quot;: 1}.</source>
        <translation>“tools”中的每一项都必须是 JSON 对象，例如 {&quot;number&quot;: 1}。</translation>
    </message>
    <message>
        <source>unknown field &quot;%1&quot; in a tool.</source>
        <translation>刀具中有未知字段“%1”。</translation>
    </message>
    <message>
        <source>the field &quot;%1&quot; appears twice in a tool.</source>
        <translation>字段“%1”在一个刀具中出现了两次。</translation>
    </message>
    <message>
        <source>&quot;measured_at&quot; is not a date and time (use ISO 8601, e.g. 2026-11-22T10:15:00Z).</source>
        <translation>“measured_at”不是日期时间（请使用 ISO 8601，例如 2026-11-22T10:15:00Z）。</translation>
    </message>
    <message>
        <source>a tool has no &quot;number&quot;.</source>
        <translation>有一个刀具没有“number”。</translation>
    </message>
    <message>
        <source>this is not valid JSON: the file is empty.</source>
        <translation>这不是有效的 JSON：文件为空。</translation>
    </message>
    <message>
        <source>this is not a Toffee tool table: the file must hold one JSON object.</source>
        <translation>这不是 Toffee 刀具表：文件必须只包含一个 JSON 对象。</translation>
    </message>
    <message>
        <source>this is not a Toffee tool table: &quot;format&quot; must be &quot;%1&quot;, before &quot;tools&quot;.</source>
        <translation>这不是 Toffee 刀具表：“format”必须是“%1”，并且位于“tools”之前。</translation>
    </message>
    <message>
        <source>&quot;version&quot; must come before &quot;tools&quot;.</source>
        <translation>“version”必须位于“tools”之前。</translation>
    </message>
    <message>
        <source>&quot;tools&quot; must be a list of tools.</source>
        <translation>“tools”必须是刀具列表。</translation>
    </message>
    <message>
        <source>this is not a Toffee tool table: &quot;format&quot; must be &quot;%1&quot;.</source>
        <translation>这不是 Toffee 刀具表：“format”必须是“%1”。</translation>
    </message>
    <message>
        <source>&quot;version&quot; must be a whole number from 1 up.</source>
        <translation>“version”必须是从 1 开始的整数。</translation>
    </message>
    <message>
        <source>this table was written by a newer Toffee (format version %1); this one reads up to version %2. Update Toffee to open it.</source>
        <translation>此表由更新版本的 Toffee 写入（格式版本 %1）；当前版本最多读取版本 %2。请更新 Toffee 后再打开。</translation>
    </message>
    <message>
        <source>&quot;units&quot; must be &quot;mm&quot; or &quot;in&quot;.</source>
        <translation>“units”必须是“mm”或“in”。</translation>
    </message>
    <message>
        <source>unknown field &quot;%1&quot; in the table.</source>
        <translation>表中有未知字段“%1”。</translation>
    </message>
    <message>
        <source>this is not valid JSON: there is more text after the table.</source>
        <translation>这不是有效的 JSON：表格之后还有其他文本。</translation>
    </message>
    <message>
        <source>the comment is not valid UTF-8 text.</source>
        <translation>注释不是有效的 UTF-8 文本。</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the field %2 appears twice.</source>
        <translation>“%1”：字段 %2 出现了两次。</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 needs a whole number.</source>
        <translation>“%1”：%2 需要整数。</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: the orientation Q must be 0 to 9.</source>
        <translation>“%1”：方向 Q 必须是 0 到 9。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a tool table field; a line holds T, P, X, Y, Z, A, B, C, U, V, W, D, I, J, Q and a ;comment.</source>
        <translation>“%1”不是刀具表字段；一行包含 T、P、X、Y、Z、A、B、C、U、V、W、D、I、J、Q 和 ;注释。</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 needs a number.</source>
        <translation>“%1”：%2 需要数字。</translation>
    </message>
    <message>
        <source>the line has no tool number (T).</source>
        <translation>该行没有刀具号（T）。</translation>
    </message>
    <message>
        <source>T%1 has no pocket (P).</source>
        <translation>T%1 没有刀位（P）。</translation>
    </message>
    <message>
        <source>T%1: pocket %2 is out of range; use %3 to %4.</source>
        <translation>T%1：刀位 %2 超出范围；请使用 %3 到 %4。</translation>
    </message>
    <message>
        <source>the file holds binary data; it is not a LinuxCNC tool table.</source>
        <translation>文件包含二进制数据；它不是 LinuxCNC 刀具表。</translation>
    </message>
    <message>
        <source>a quoted field is never closed; add the closing quote (&quot;).</source>
        <translation>有一个带引号的字段没有结束；请补上结束引号（&quot;）。</translation>
    </message>
    <message>
        <source>text after a closing quote; put the whole field in quotes.</source>
        <translation>结束引号之后还有文本；请把整个字段放在引号内。</translation>
    </message>
    <message>
        <source>a quote (&quot;) inside an unquoted field; put the whole field in quotes and double the quote.</source>
        <translation>未加引号的字段中有引号（&quot;）；请把整个字段放在引号内，并将引号写两次。</translation>
    </message>
    <message>
        <source>the file holds binary data; it is not a CSV table.</source>
        <translation>文件包含二进制数据；它不是 CSV 表格。</translation>
    </message>
    <message>
        <source>the file is not UTF-8 text; save it from the spreadsheet as &quot;CSV UTF-8&quot;.</source>
        <translation>文件不是 UTF-8 文本；请在电子表格软件中另存为“CSV UTF-8”。</translation>
    </message>
    <message>
        <source>the file is empty; a CSV tool table starts with a header row such as &quot;number,pocket,description,...&quot;.</source>
        <translation>文件为空；CSV 刀具表以表头行开始，例如“number,pocket,description,...”。</translation>
    </message>
    <message>
        <source>the column &quot;%1&quot; appears twice in the header.</source>
        <translation>列“%1”在表头中出现了两次。</translation>
    </message>
    <message>
        <source>the header has no &quot;number&quot; column.</source>
        <translation>表头没有“number”列。</translation>
    </message>
    <message>
        <source>this row has %1 fields but the header has %2.</source>
        <translation>此行有 %1 个字段，但表头有 %2 个。</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; is not a number.</source>
        <translation>%1“%2”不是数字。</translation>
    </message>
    <message>
        <source>%1 &quot;%2&quot; is not a whole number.</source>
        <translation>%1“%2”不是整数。</translation>
    </message>
    <message>
        <source>the row has no tool number.</source>
        <translation>该行没有刀具号。</translation>
    </message>
    <message>
        <source>measured_at &quot;%1&quot; is not a date and time (use ISO 8601, e.g. 2026-11-22T10:15:00Z).</source>
        <translation>measured_at“%1”不是日期时间（请使用 ISO 8601，例如 2026-11-22T10:15:00Z）。</translation>
    </message>
    <message>
        <source>units &quot;%1&quot; must be mm or in.</source>
        <translation>单位“%1”必须是 mm 或 in。</translation>
    </message>
    <message>
        <source>this row is in %1 but the rows above are in %2; a table has one unit.</source>
        <translation>此行单位为 %1，但上面各行为 %2；一张表只能有一种单位。</translation>
    </message>
    <message>
        <source>T%1 cannot be written: %2 offset numbers go from 1 to %3.</source>
        <translation>无法写入 T%1：%2 的补偿号为 1 到 %3。</translation>
    </message>
    <message>
        <source>T%1 cannot be written: LinuxCNC&apos;s G10 L1 needs a tool number from 1 up.</source>
        <translation>无法写入 T%1：LinuxCNC 的 G10 L1 需要从 1 开始的刀具号。</translation>
    </message>
    <message>
        <source>No tool has a measured TLO to write; probe the tools first.</source>
        <translation>没有刀具有测得的 TLO 可写入；请先对刀。</translation>
    </message>
    <message>
        <source>There is no tool %1 in the table.</source>
        <translation>表中没有刀具 %1。</translation>
    </message>
    <message>
        <source>The table is empty.</source>
        <translation>表格为空。</translation>
    </message>
    <message>
        <source>Toffee does not know how the FAGOR 8055M programs its offset table; enter the offsets at the control, or export for another dialect.</source>
        <translation>Toffee 不知道 FAGOR 8055M 如何编程其补偿表；请在控制器上输入补偿，或导出为其他控制器。</translation>
    </message>
    <message>
        <source>Unknown controller.</source>
        <translation>未知的控制器。</translation>
    </message>
    <message>
        <source>%1… (%2 characters)</source>
        <translation>%1…（共 %2 个字符）</translation>
    </message>
    <message>
        <source>%1… (%2 bytes)</source>
        <translation>%1…（共 %2 字节）</translation>
    </message>
    <message>
        <source>it is a named pipe (FIFO), not a file; Toffee opens only regular files.</source>
        <translation>这是命名管道（FIFO），不是文件；Toffee 只打开普通文件。</translation>
    </message>
    <message>
        <source>it is a device, not a file; Toffee opens only regular files.</source>
        <translation>这是设备，不是文件；Toffee 只打开普通文件。</translation>
    </message>
    <message>
        <source>it is a folder, not a file.</source>
        <translation>这是文件夹，不是文件。</translation>
    </message>
    <message>
        <source>it is a socket, not a file; Toffee opens only regular files.</source>
        <translation>这是套接字，不是文件；Toffee 只打开普通文件。</translation>
    </message>
    <message>
        <source>it is not a regular file; Toffee opens only regular files.</source>
        <translation>这不是普通文件；Toffee 只打开普通文件。</translation>
    </message>
    <message>
        <source>no file name was given.</source>
        <translation>没有给出文件名。</translation>
    </message>
    <message>
        <source>%1: the file is %2 MB; Toffee reads files of at most %3 MB.</source>
        <translation>%1：文件大小为 %2 MB；Toffee 最多读取 %3 MB 的文件。</translation>
    </message>
    <message>
        <source>%1: cannot save: %2 The old file is unchanged.</source>
        <translation>%1：无法保存：%2 旧文件保持不变。</translation>
    </message>
    <message>
        <source>%1: cannot save: %2 Nothing was written.</source>
        <translation>%1：无法保存：%2 未写入任何内容。</translation>
    </message>
    <message>
        <source>the file could not be written</source>
        <translation>无法写入文件</translation>
    </message>
    <message>
        <source>the table would take more than %1 MB, more than Toffee reads back; shorten the notes or split the table.</source>
        <translation>该表将超过 %1 MB，超出 Toffee 能读回的大小；请缩短备注或拆分表格。</translation>
    </message>
    <message>
        <source>&quot;%1&quot;: %2 is out of range; use %3 to %4.</source>
        <translation>“%1”：%2 超出范围；请使用 %3 到 %4。</translation>
    </message>
    <message>
        <source>%1: there is not enough memory to read this table (the file is %2 MB).</source>
        <translation>%1：内存不足，无法读取此表（文件大小为 %2 MB）。</translation>
    </message>
    <message>
        <source>the comment &quot;%1&quot; is longer than a description may be (%2 characters).</source>
        <translation>注释“%1”超过描述允许的长度（%2 个字符）。</translation>
    </message>
    <message>
        <source>the field &quot;%1&quot; is longer than %2 KB; no column of a tool table holds that much.</source>
        <translation>字段“%1”超过 %2 KB；刀具表的任何列都容纳不了这么多。</translation>
    </message>
    <message>
        <source>the header has more than %1 columns, more than a tool table has.</source>
        <translation>表头超过 %1 列，多于刀具表的列数。</translation>
    </message>
    <message>
        <source>this row has more fields than the header&apos;s %1.</source>
        <translation>此行的字段多于表头的 %1 个。</translation>
    </message>
    <message>
        <source>%1: cannot save: %2</source>
        <translation>%1：无法保存：%2</translation>
    </message>
    <message>
        <source>the folder %1 does not exist.</source>
        <translation>文件夹 %1 不存在。</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>T%1 has no measured TLO to write; probe it first.</source>
        <translation>T%1 没有可写入的已测 TLO；请先对其对刀。</translation>
    </message>
    <message>
        <source>An Aerotech program sets the offsets of one tool at a time: choose the tool.</source>
        <translation>Aerotech 程序一次只设置一把刀具的补偿：请选择刀具。</translation>
    </message>
    <message>
        <source>a TLO set by hand needs its value; the measured TLO is empty.</source>
        <translation>手动设置的 TLO 需要数值；测得的 TLO 为空。</translation>
    </message>
    <message>
        <source>A LinuxCNC table cannot mark a tool that failed its break test: %1 would no longer be marked.</source>
        <translation>LinuxCNC 刀具表无法标记未通过断刀检测的刀具：%1 将不再被标记。</translation>
    </message>
    <message>
        <source>break_test &quot;%1&quot; must be failed, passed or empty.</source>
        <translation>break_test &quot;%1&quot; 必须是 failed、passed 或留空。</translation>
    </message>
    <message>
        <source>reference MCS Z</source>
        <translation>基准 MCS Z</translation>
    </message>
    <message>
        <source>%1 is %2 %3; it cannot be negative.</source>
        <translation>%1 为 %2 %3；不能为负数。</translation>
    </message>
    <message>
        <source>the diameter</source>
        <translation>直径</translation>
    </message>
    <message>
        <source>the flute length</source>
        <translation>刃长</translation>
    </message>
    <message>
        <source>the length below the holder</source>
        <translation>夹头下方长度</translation>
    </message>
    <message>
        <source>the overall length</source>
        <translation>总长</translation>
    </message>
    <message>
        <source>%1: cannot open it.</source>
        <translation>%1：无法打开。</translation>
    </message>
    <message>
        <source>Fusion tool library (JSON)</source>
        <translation>Fusion 刀具库（JSON）</translation>
    </message>
    <message>
        <source>Fusion tool library (.tools)</source>
        <translation>Fusion 刀具库（.tools）</translation>
    </message>
    <message>
        <source>HSM tool library (.hsmlib)</source>
        <translation>HSM 刀具库（.hsmlib）</translation>
    </message>
    <message>
        <source>Makera CAM program&apos;s tool header</source>
        <translation>Makera CAM 程序的刀具头</translation>
    </message>
    <message>
        <source>the library holds no tools; nothing to import.</source>
        <translation>该刀具库不含任何刀具；没有可导入的内容。</translation>
    </message>
    <message>
        <source>number %1 is taken already (%2); each tool needs a number of its own.</source>
        <translation>编号 %1 已被使用（%2）；每把刀具都需要自己的编号。</translation>
    </message>
    <message>
        <source>line %1</source>
        <translation>第 %1 行</translation>
    </message>
    <message>
        <source>%1: not a CAM tool library Toffee reads (.json, .tools, .hsmlib, or a G-code program with Makera CAM&apos;s tool header).</source>
        <translation>%1：不是 Toffee 可读取的 CAM 刀具库（.json、.tools、.hsmlib，或带有 Makera CAM 刀具头的 G 代码程序）。</translation>
    </message>
    <message>
        <source>it unpacks to more than %1 MB; Toffee reads libraries of at most %1 MB.</source>
        <translation>解压后超过 %1 MB；Toffee 只读取不超过 %1 MB 的刀具库。</translation>
    </message>
    <message>
        <source>this is not a .tools archive Toffee can read: %1.</source>
        <translation>这不是 Toffee 能读取的 .tools 归档：%1。</translation>
    </message>
    <message>
        <source>it cannot be unpacked: %1.</source>
        <translation>无法解压：%1。</translation>
    </message>
    <message>
        <source>it is not a zip archive, or one cut short (there is no zip directory at its end)</source>
        <translation>它不是 zip 归档，或是一个被截断的归档（末尾没有 zip 目录）</translation>
    </message>
    <message>
        <source>two of its entries have the same name, so it cannot be told which one is meant</source>
        <translation>其中两个条目同名，无法确定指的是哪一个</translation>
    </message>
    <message>
        <source>the archive is damaged (its directory and its entries disagree)</source>
        <translation>归档已损坏（其目录与条目不一致）</translation>
    </message>
    <message>
        <source>it is one part of an archive split over several files</source>
        <translation>它是拆分为多个文件的归档中的一部分</translation>
    </message>
    <message>
        <source>the archive is damaged (what it unpacks to fails its checksum)</source>
        <translation>归档已损坏（解压出的内容未通过校验和）</translation>
    </message>
    <message>
        <source>it is compressed in a way Toffee cannot unpack (Fusion&apos;s own archives use deflate)</source>
        <translation>它的压缩方式 Toffee 无法解压（Fusion 自己的归档使用 deflate）</translation>
    </message>
    <message>
        <source>it is encrypted; Toffee reads archives without a password</source>
        <translation>它已加密；Toffee 只读取没有密码的归档</translation>
    </message>
    <message>
        <source>its compressed data is damaged</source>
        <translation>其压缩数据已损坏</translation>
    </message>
    <message>
        <source>the archive is truncated (it ends early)</source>
        <translation>归档不完整（提前结束）</translation>
    </message>
    <message>
        <source>there is not enough memory to unpack it</source>
        <translation>内存不足，无法解压</translation>
    </message>
    <message>
        <source>libzip says: %1</source>
        <translation>libzip 报告：%1</translation>
    </message>
    <message>
        <source>this is not a .tools archive: the file is empty.</source>
        <translation>这不是 .tools 归档：文件为空。</translation>
    </message>
    <message>
        <source>the archive holds no %1; a Fusion .tools file is a zip archive with the library in %1.</source>
        <translation>归档中没有 %1；Fusion 的 .tools 文件是一个 zip 归档，刀具库保存在 %1 中。</translation>
    </message>
    <message>
        <source>the archive holds %1 twice (%2 and %3); Toffee will not guess which one is the library.</source>
        <translation>归档中有两个 %1（%2 和 %3）；Toffee 不会猜测哪一个才是刀具库。</translation>
    </message>
    <message>
        <source>a list</source>
        <translation>一个列表</translation>
    </message>
    <message>
        <source>an object</source>
        <translation>一个对象</translation>
    </message>
    <message>
        <source>null</source>
        <translation>null</translation>
    </message>
    <message>
        <source>this is not a Fusion tool library: that is a JSON object with &quot;data&quot;, a list of tools.</source>
        <translation>这不是 Fusion 刀具库：刀具库是一个带有“data”（刀具列表）的 JSON 对象。</translation>
    </message>
    <message>
        <source>tool %1 in &quot;data&quot;</source>
        <translation>“data”中的第 %1 把刀具</translation>
    </message>
    <message>
        <source>it is %1, not an object.</source>
        <translation>它是 %1，不是对象。</translation>
    </message>
    <message>
        <source>%1=%2 is not a number.</source>
        <translation>%1=%2 不是数字。</translation>
    </message>
    <message>
        <source>number=%1 is not a tool number.</source>
        <translation>number=%1 不是刀具号。</translation>
    </message>
    <message>
        <source>this tool line has no number=…; Toffee needs the T number.</source>
        <translation>该刀具行没有 number=…；Toffee 需要 T 号。</translation>
    </message>
    <message>
        <source>%1 is in this tool line twice (%1=%2 and %1=%3); Toffee will not guess which one is meant.</source>
        <translation>%1 在这一刀具行中出现了两次（%1=%2 和 %1=%3）；Toffee 不会猜测指的是哪一个。</translation>
    </message>
    <message>
        <source>this is not a text program: it holds binary data (a NUL byte), which a G-code program never does.</source>
        <translation>这不是文本程序：其中含有二进制数据（NUL 字节），而 G 代码程序从不含有这些。</translation>
    </message>
    <message>
        <source>the program&apos;s first %1 MB are all comments; Toffee reads the tool header only from the start of a program.</source>
        <translation>程序的前 %1 MB 全是注释；Toffee 只从程序开头读取刀具头。</translation>
    </message>
    <message>
        <source>this program has no Makera CAM tool header (&quot;;@MKR|TOOL|number=…&quot; lines before the program body); there are no tools to import from it.</source>
        <translation>该程序没有 Makera CAM 刀具头（程序主体之前的“;@MKR|TOOL|number=…”行）；没有可从中导入的刀具。</translation>
    </message>
    <message>
        <source>just now</source>
        <translation>刚刚</translation>
    </message>
    <message>
        <source>%1 min ago</source>
        <translation>%1 分钟前</translation>
    </message>
    <message>
        <source>%1 h ago</source>
        <translation>%1 小时前</translation>
    </message>
    <message>
        <source>%1 days ago</source>
        <translation>%1 天前</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 秒</translation>
    </message>
    <message>
        <source>%1 min</source>
        <translation>%1 分钟</translation>
    </message>
    <message>
        <source>%1 h %2 min</source>
        <translation>%1 小时 %2 分钟</translation>
    </message>
    <message>
        <source>a rack is &quot;none&quot;, or tool numbers and ranges such as 1-6 or 1,2,5-8.</source>
        <translation>刀库应为“none”，或刀具号及范围，例如 1-6 或 1,2,5-8。</translation>
    </message>
    <message>
        <source>the job check finds %1; the first, on line %2: %3 Fix them before preparing the program (Check Job, or toffee-cli job check, lists them). Nothing was written.</source>
        <translation>作业检查发现 %1；第一个在第 %2 行：%3 请先修正这些错误，再准备程序（“检查作业”或 toffee-cli job check 会列出它们）。未写入任何内容。</translation>
    </message>
    <message>
        <source>an error</source>
        <translation>1 个错误</translation>
    </message>
    <message>
        <source>%1 errors</source>
        <translation>%1 个错误</translation>
    </message>
    <message>
        <source>Preparing was cancelled; nothing was written.</source>
        <translation>准备已取消；未写入任何内容。</translation>
    </message>
    <message>
        <source>Say where the prepared program goes: no file name was given.</source>
        <translation>请指定准备好的程序保存到哪里：没有给出文件名。</translation>
    </message>
    <message>
        <source>%1: the prepared program must go to another file than the program itself.</source>
        <translation>%1：准备好的程序必须保存到原程序以外的文件。</translation>
    </message>
    <message>
        <source>%1 is the tool table: the prepared program must go to another file.</source>
        <translation>%1 是刀具表：准备好的程序必须保存到其他文件。</translation>
    </message>
    <message>
        <source>T%1 is not in the table: it is measured at its change.</source>
        <translation>T%1 不在刀具表中：换刀时将对其对刀。</translation>
    </message>
    <message>
        <source>T%1 has no stored TLO: it is measured at its change.</source>
        <translation>T%1 没有已存 TLO：换刀时将对其对刀。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was set by hand, not measured: it is measured at its change.</source>
        <translation>T%1 的 TLO 是手动设置的，并非测得：换刀时将对其对刀。</translation>
    </message>
    <message>
        <source>T%1 failed its last break test: it is measured at its change.</source>
        <translation>T%1 未通过上次断刀检测：换刀时将对其对刀。</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO is older than the stale limit (%2 d): it is measured at its change.</source>
        <translation>T%1 的已存 TLO 已超过过期期限（%2 天）：换刀时将对其对刀。</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO was measured against reference MCS Z %2, but the machine&apos;s is %3: it is measured at its change.</source>
        <translation>T%1 的已存 TLO 是相对于基准 MCS Z %2 测得的，但机床的基准为 %3：换刀时将对其对刀。</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO does not say which reference it was measured against: it is measured at its change.</source>
        <translation>T%1 的已存 TLO 未注明是相对哪个基准测量的：换刀时将重新对刀。</translation>
    </message>
    <message>
        <source>Toffee&apos;s zip reader %1 is missing, so .tools archives cannot be read; reinstall Toffee.</source>
        <translation>Toffee 的 zip 读取模块 %1 缺失，因此无法读取 .tools 归档；请重新安装 Toffee。</translation>
    </message>
    <message>
        <source>Toffee&apos;s zip reader %1 cannot be loaded (%2); reinstall Toffee.</source>
        <translation>无法加载 Toffee 的 zip 读取模块 %1（%2）；请重新安装 Toffee。</translation>
    </message>
    <message>
        <source>column %1: %2</source>
        <translation>第 %1 列：%2</translation>
    </message>
    <message>
        <source>this is not valid JSON: there is more text after the value.</source>
        <translation>这不是有效的 JSON：值之后还有其他文本。</translation>
    </message>
    <message>
        <source>this is not valid JSON: there is more text after the library.</source>
        <translation>这不是有效的 JSON：刀具库之后还有其他文本。</translation>
    </message>
    <message>
        <source>the machine reports no reference (an uncalibrated reference of 0, or a firmware that does not say), so T%1&apos;s stored TLO cannot be checked against it: it is measured at its change.</source>
        <translation>机床未报告基准（基准为 0 即未校准，或固件不报告），因此无法据此检查 T%1 的已存 TLO：换刀时将对其测量。</translation>
    </message>
    <message>
        <source>T%1 is not break-tested: the firmware&apos;s break test takes T0 and every tool from T9 up for its wireless probe, and would halt.</source>
        <translation>T%1 不做断刀检测：固件的断刀检测把 T0 及 T9 以上的每把刀都当作其无线探头，并会停机。</translation>
    </message>
    <message>
        <source>T%1 cannot be written: grblHAL&apos;s G10 L1 needs a tool number from 1 up.</source>
        <translation>无法写入 T%1：grblHAL 的 G10 L1 需要从 1 起的刀具号。</translation>
    </message>
    <message>
        <source>halt reason %1</source>
        <translation>停机原因 %1</translation>
    </message>
    <message>
        <source>The machine was stopped (Stop, Ctrl-X or the stop button).</source>
        <translation>机床已被停止（停止命令、Ctrl-X 或停止按钮）。</translation>
    </message>
    <message>
        <source>Homing failed, or the machine has not been homed.</source>
        <translation>回零失败，或机床尚未回零。</translation>
    </message>
    <message>
        <source>The probe did not touch within its safety margin: the tool may be missing, broken or much shorter than expected.</source>
        <translation>探针在安全余量内未触发：刀具可能缺失、已断，或比预期短得多。</translation>
    </message>
    <message>
        <source>Measuring on the tool setter failed: the setter was not touched (the tool may be missing or much shorter than expected), a break test found the tool broken, or the tolerance was too small.</source>
        <translation>在对刀仪上测量失败：对刀仪未被触碰（刀具可能缺失或比预期短得多）、断刀检测判定刀具已断，或公差过小。</translation>
    </message>
    <message>
        <source>The tool changer could not home.</source>
        <translation>换刀装置无法回零。</translation>
    </message>
    <message>
        <source>The tool asked for is not a valid tool.</source>
        <translation>请求的刀具不是有效刀具。</translation>
    </message>
    <message>
        <source>The spindle already holds a tool.</source>
        <translation>主轴上已有刀具。</translation>
    </message>
    <message>
        <source>The spindle overheated.</source>
        <translation>主轴过热。</translation>
    </message>
    <message>
        <source>A move went beyond the machine&apos;s travel (soft limit).</source>
        <translation>某个移动超出了机床行程（软限位）。</translation>
    </message>
    <message>
        <source>The cover is open.</source>
        <translation>防护罩已打开。</translation>
    </message>
    <message>
        <source>The probe is not valid.</source>
        <translation>探针无效。</translation>
    </message>
    <message>
        <source>The emergency stop is pressed.</source>
        <translation>急停按钮已按下。</translation>
    </message>
    <message>
        <source>The power supply overheated.</source>
        <translation>电源过热。</translation>
    </message>
    <message>
        <source>The machine has not been homed.</source>
        <translation>机床尚未回零。</translation>
    </message>
    <message>
        <source>A crash was detected.</source>
        <translation>检测到碰撞。</translation>
    </message>
    <message>
        <source>The machine halted (reason %1).</source>
        <translation>机床已停机（原因 %1）。</translation>
    </message>
    <message>
        <source>This halt needs a reset of the controller.</source>
        <translation>此次停机需要复位控制器。</translation>
    </message>
    <message>
        <source>This halt needs the machine switched off and on again.</source>
        <translation>此次停机需要关闭机床电源后重新开启。</translation>
    </message>
    <message>
        <source>Check the machine, then Unlock ($X).</source>
        <translation>检查机床，然后解锁（$X）。</translation>
    </message>
    <message>
        <source>The tool setter was never touched: the tool may be missing, broken or much shorter than expected. Check the spindle, then Unlock.</source>
        <translation>对刀仪始终未被触碰：刀具可能缺失、已断或比预期短得多。请检查主轴，然后解锁。</translation>
    </message>
    <message>
        <source>Unlock, home the machine, then try again.</source>
        <translation>请解锁、让机床回原点，然后重试。</translation>
    </message>
    <message>
        <source>the cutter type is %1 characters long; keep it to %2.</source>
        <translation>刀具类型长 %1 个字符；请不超过 %2 个。</translation>
    </message>
    <message>
        <source>overall length</source>
        <translation>总长</translation>
    </message>
    <message>
        <source>the overall length cannot be negative.</source>
        <translation>总长不能为负。</translation>
    </message>
    <message>
        <source>a life limit in minutes must be more than 0 and at most %1; leave it empty for none.</source>
        <translation>以分钟计的寿命上限必须大于 0 且不超过 %1；留空表示无上限。</translation>
    </message>
    <message>
        <source>a life limit in uses must be a whole number from 1 to %1; leave it empty for none.</source>
        <translation>以使用次数计的寿命上限必须是 1 到 %1 的整数；留空表示无上限。</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no place for tool life limits: they are not saved.</source>
        <translation>LinuxCNC 刀具表没有存放刀具寿命上限的位置：不会保存。</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no place for the cutter&apos;s type and overall length: they are not saved, and an import can then tell a new cutter only by its diameter.</source>
        <translation>LinuxCNC 刀具表没有存放刀具类型和总长的位置：不会保存，之后导入只能凭直径识别新刀具。</translation>
    </message>
    <message>
        <source>dated in the future (%1)</source>
        <translation>日期在未来（%1）</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO is dated %2, in the future: a clock was wrong, and when it was measured is not known. It is measured at its change.</source>
        <translation>T%1 存储的刀长补偿日期为 %2，在未来：某个时钟有误，测量时间未知。将在换刀时测量。</translation>
    </message>
    <message>
        <source>T%1&apos;s %2 event %3 holds a TLO of %4 mm, beyond any tool (%5 mm at most).</source>
        <translation>T%1 的 %2 事件 %3 含有 %4 mm 的刀长补偿，超出任何刀具（最多 %5 mm）。</translation>
    </message>
    <message>
        <source>The tool changer found no tool where one should be (an empty rack pocket), or was given no tool.</source>
        <translation>换刀装置在应有刀具的位置没有找到刀具（刀库刀位为空），或未指定刀具。</translation>
    </message>
    <message>
        <source>&quot;tlo_source&quot; must be &quot;probe&quot;, &quot;manual&quot; or &quot;pulled&quot;.</source>
        <translation>&quot;tlo_source&quot; 必须是 &quot;probe&quot;、&quot;manual&quot; 或 &quot;pulled&quot;。</translation>
    </message>
    <message>
        <source>tlo_source &quot;%1&quot; must be probe, manual, pulled or empty.</source>
        <translation>tlo_source &quot;%1&quot; 必须是 probe、manual、pulled 或为空。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was read from the controller&apos;s table, not measured: it is measured at its change.</source>
        <translation>T%1 的 TLO 是从控制器的刀具表读取的，并非测量所得：换刀时将进行测量。</translation>
    </message>
    <message>
        <source>a cutter has 1 to %1 cutting edges; leave it empty when unknown.</source>
        <translation>刀具有 1 到 %1 个刃；未知时留空。</translation>
    </message>
    <message>
        <source>A LinuxCNC table has no place for how a tool is probed (its edges, touches, touch-off point, latch feed and spread limit): they are not saved, and each tool is then probed once at the setter&apos;s centre.</source>
        <translation>LinuxCNC 刀具表无法保存刀具的测量方式（刃数、触碰次数、触碰点、慢速进给和差值上限）：这些不会保存，之后每把刀具只在对刀仪中心测量一次。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; must be true or false.</source>
        <translation>“%1”必须为 true 或 false。</translation>
    </message>
    <message>
        <source>unknown column &quot;%1&quot; in the header; the columns are %2.</source>
        <translation>表头中有未知列“%1”；可用的列为 %2。</translation>
    </message>
    <message>
        <source>probe_turn &quot;%1&quot; must be yes, no or empty.</source>
        <translation>probe_turn“%1”必须为 yes、no 或留空。</translation>
    </message>
</context>
<context>
    <name>Toffee::About</name>
    <message>
        <source>About Toffee</source>
        <translation>关于 Toffee</translation>
    </message>
    <message>
        <source>Toffee %1</source>
        <translation>Toffee %1</translation>
    </message>
    <message>
        <source>The tool offset manager: a CNC machine&apos;s tool table and tool length offsets, kept right.

Licensed under the GNU General Public License, version 3 or later.</source>
        <translation>刀具偏置管理器：让 CNC 机床的刀具表和刀具长度补偿保持正确。

依据 GNU 通用公共许可证第 3 版或（由您选择）任何更新版本授权。</translation>
    </message>
</context>
<context>
    <name>Toffee::AddToolCommand</name>
    <message>
        <source>Add tool T%1</source>
        <translation>添加刀具 T%1</translation>
    </message>
</context>
<context>
    <name>Toffee::AutoSave</name>
    <message>
        <source>Cannot create the folder for unsaved edits, %1.</source>
        <translation>无法创建保存未保存修改的文件夹 %1。</translation>
    </message>
    <message>
        <source>Cannot write in the folder for unsaved edits, %1.</source>
        <translation>无法写入保存未保存修改的文件夹 %1。</translation>
    </message>
</context>
<context>
    <name>Toffee::BreakTestPanel</name>
    <message>
        <source>Run Break Test</source>
        <translation>运行断刀检测</translation>
    </message>
    <message>
        <source>Break-test tolerance in millimetres</source>
        <translation>断刀检测公差（毫米）</translation>
    </message>
    <message>
        <source>How far the new measurement may differ from the stored TLO; at least %1 mm, %2 mm by default.</source>
        <translation>新测量值与已存刀长补偿之间允许的差值；至少 %1 mm，默认 %2 mm。</translation>
    </message>
    <message>
        <source>Run the tool break test</source>
        <translation>运行断刀检测</translation>
    </message>
    <message>
        <source>Re-measure the tool and compare it with its stored TLO (M491.1) — F6</source>
        <translation>重新测量刀具并与已存刀长补偿比较（M491.1）— F6</translation>
    </message>
    <message>
        <source>Tolerance:</source>
        <translation>公差：</translation>
    </message>
    <message>
        <source>Stored TLO:</source>
        <translation>已存 TLO：</translation>
    </message>
    <message>
        <source>Measured TLO:</source>
        <translation>测得 TLO：</translation>
    </message>
    <message>
        <source>Difference:</source>
        <translation>差值：</translation>
    </message>
    <message>
        <source>BROKEN TOOL</source>
        <translation>刀具已断</translation>
    </message>
    <message>
        <source>The break test did not run</source>
        <translation>断刀检测未能运行</translation>
    </message>
    <message>
        <source>Broken tool</source>
        <translation>断刀</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>解锁</translation>
    </message>
    <message>
        <source>Leave Halted</source>
        <translation>保持停机</translation>
    </message>
    <message>
        <source>The machine reports no tool in the spindle.</source>
        <translation>机床报告主轴上没有刀具。</translation>
    </message>
    <message>
        <source>T%1 has no TLO in the table: the test compares against whatever TLO the machine holds%2, which may not be T%1&apos;s.</source>
        <translation>T%1 在刀具表中没有 TLO：检测将与机床当前保存的 TLO%2 比较，而它可能不是 T%1 的。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was set by hand (%3), not measured: if that value is not the tool&apos;s real length, the test reports the tool broken and halts the machine.</source>
        <translation>T%1 的 TLO %2 是手动设置的（%3），未测量：如果该值不是刀具的实际长度，检测会报告断刀并使机床停机。</translation>
    </message>
    <message>
        <source>Break-test %1?</source>
        <translation>对 %1 进行断刀检测？</translation>
    </message>
    <message>
        <source>The machine will move to the tool setter and measure %1 again, then compare it with its TLO (tolerance %2). Keep hands clear.</source>
        <translation>机床将移动到对刀仪，重新测量 %1，然后与其 TLO 比较（公差 %2）。手请远离机床。</translation>
    </message>
    <message>
        <source>The tool</source>
        <translation>刀具</translation>
    </message>
    <message>
        <source>%1 may be broken. The machine has halted, and the table marks %1 until it is probed again.</source>
        <translation>%1 可能已断。机床已停机，刀具表会一直标记 %1，直到重新对刀。</translation>
    </message>
    <message>
        <source>T%1: BROKEN TOOL</source>
        <translation>T%1：断刀</translation>
    </message>
    <message>
        <source>T%1 OK: within %2.</source>
        <translation>T%1 正常：在 %2 以内。</translation>
    </message>
    <message>
        <source>Tool OK: within %1.</source>
        <translation>刀具正常：在 %1 以内。</translation>
    </message>
    <message>
        <source>The TLO it was compared against was set by hand, not measured: if that value was not the tool&apos;s real length, the tool may be whole. Look at the tool before you replace it, then probe it.</source>
        <translation>用于比较的 TLO 是手动设置的，而非测量所得：如果该值不是刀具的真实长度，刀具可能完好。更换前请先检查刀具，然后对刀。</translation>
    </message>
    <message>
        <source>The spindle is empty: load a tool first (Rack ▸ Load).</source>
        <translation>主轴为空：请先装入刀具（刀库 ▸ 装入）。</translation>
    </message>
    <message>
        <source>The machine holds TLO %1 but the table holds %2 for T%3: Toffee sets the table&apos;s %2 first, and the machine compares the tool with it.</source>
        <translation>机床的 TLO 为 %1，但刀具表中 T%3 为 %2：Toffee 会先设置刀具表中的 %2，机床再用它与刀具比较。</translation>
    </message>
    <message>
        <source>%1 may be broken. The machine is stopped and lifted (not halted), and the table marks %1 until it is probed again.</source>
        <translation>%1 可能已断。机床已停止并抬起（未停机锁定），刀具表会标记 %1，直到再次测量。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was read from the controller&apos;s table (%3), not measured: if that value is not the tool&apos;s real length, the test reports the tool broken.</source>
        <translation>T%1 的 TLO %2 是从控制器的刀具表读取的（%3），并非测量所得：若该值不是刀具的真实长度，测试会报告刀具断裂。</translation>
    </message>
</context>
<context>
    <name>Toffee::CarveraConsole</name>
    <message>
        <source>%1 probes the tool: the machine moves to the tool setter, and the TLO it measures is recorded in the table.</source>
        <translation>%1 会对刀：机床移动到对刀仪，测得的 TLO 将记录到刀具表中。</translation>
    </message>
    <message>
        <source>The Carvera works in millimetres only: G20 (inches) halts it. Use G21.</source>
        <translation>Carvera 只使用毫米：G20（英寸）会使其停机。请使用 G21。</translation>
    </message>
    <message>
        <source>M491.1 runs a break test: the machine moves to the tool setter and probes the tool. Use Machine ▸ Break Test to have the result recorded in the table.</source>
        <translation>M491.1 执行断刀检测：机床移动到对刀仪并测量刀具。请使用“机床 ▸ 断刀检测”，以便将结果记录到刀具表中。</translation>
    </message>
    <message>
        <source>M493.3 needs Z (the TLO) or H (the tool tip&apos;s height above Z0).</source>
        <translation>M493.3 需要 Z（TLO）或 H（刀尖在 Z0 以上的高度）。</translation>
    </message>
    <message>
        <source>Typed, M493.3 H can set a TLO more than 100 mm off: after an M493.3 Z the community firmware measures H from the TLO instead of the tool&apos;s height. Under &quot;Set the offset by hand&quot;, choose Gauge height above Z0: Toffee works the TLO out from the position and sends it as M493.3 Z.</source>
        <translation>手动输入的 M493.3 H 可能使 TLO 偏差超过 100 mm：在 M493.3 Z 之后，社区固件从 TLO 而不是刀具高度起算 H。请在“手动设置补偿”中选择“Z0 以上的量规高度”：Toffee 会根据位置算出 TLO 并以 M493.3 Z 发送。</translation>
    </message>
    <message>
        <source>The tool length offset</source>
        <translation>刀具长度补偿</translation>
    </message>
    <message>
        <source>%1 changes the tool length offset the next cut uses. The table records it as set by hand.</source>
        <translation>%1 会更改下一次切削所用的刀具长度补偿。刀具表会将其记录为手动设置。</translation>
    </message>
    <message>
        <source>M493.2 needs a tool (M493.2 T2): without one the machine halts.</source>
        <translation>M493.2 需要指定刀具（M493.2 T2）：否则机床会停机。</translation>
    </message>
    <message>
        <source>M493.2 makes T%1 the active tool but keeps the TLO in force now (another tool&apos;s, or none): T%1&apos;s own is not set. Probe T%1 or restore its TLO before cutting.</source>
        <translation>M493.2 将 T%1 设为当前刀具，但保留当前生效的 TLO（另一把刀具的，或没有）：T%1 自己的 TLO 未设置。切削前请测量 T%1 或恢复其 TLO。</translation>
    </message>
    <message>
        <source>M6 T%1 changes the tool: the machine moves, and then probes T%1 on the tool setter.</source>
        <translation>M6 T%1 会换刀：机床会移动，然后在对刀仪上对 T%1 对刀。</translation>
    </message>
</context>
<context>
    <name>Toffee::ConflictDialog</name>
    <message>
        <source>not measured</source>
        <translation>未测量</translation>
    </message>
    <message>
        <source>set by hand</source>
        <translation>手动设置</translation>
    </message>
    <message>
        <source>probed</source>
        <translation>对刀测得</translation>
    </message>
    <message>
        <source>time unknown</source>
        <translation>时间未知</translation>
    </message>
    <message>
        <source>%1 (%2, %3)</source>
        <translation>%1（%2，%3）</translation>
    </message>
    <message>
        <source>Removed from the table</source>
        <translation>已从刀具表中删除</translation>
    </message>
    <message>
        <source>Tools changed on another station</source>
        <translation>在另一工作站上被更改的刀具</translation>
    </message>
    <message>
        <source>Changed on Another Station</source>
        <translation>已在另一工作站上更改</translation>
    </message>
    <message>
        <source>What happened</source>
        <translation>发生了什么</translation>
    </message>
    <message>
        <source>Another station changed this tool since you opened the table, and so did you. Choose which version the library keeps. Everything else is saved.</source>
        <translation>自您打开刀具表以来，另一工作站更改了这把刀具，您也更改了它。请选择刀具库保留哪个版本。其他内容均已保存。</translation>
    </message>
    <message>
        <source>Another station changed these %1 tools since you opened the table, and so did you. Choose, for each, which version the library keeps. Everything else is saved.</source>
        <translation>自您打开刀具表以来，另一工作站更改了这 %1 把刀具，您也更改了它们。请为每把刀具选择刀具库保留哪个版本。其他内容均已保存。</translation>
    </message>
    <message>
        <source>Their version and yours, per tool</source>
        <translation>每把刀具的对方版本和您的版本</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>刀具</translation>
    </message>
    <message>
        <source>Theirs</source>
        <translation>对方的</translation>
    </message>
    <message>
        <source>Mine</source>
        <translation>我的</translation>
    </message>
    <message>
        <source>Keep</source>
        <translation>保留</translation>
    </message>
    <message>
        <source>Apply the choices or decide later</source>
        <translation>应用所做的选择，或稍后决定</translation>
    </message>
    <message>
        <source>&amp;Apply Choices</source>
        <translation>应用选择(&amp;A)</translation>
    </message>
    <message>
        <source>Apply the choices</source>
        <translation>应用所做的选择</translation>
    </message>
    <message>
        <source>Decide &amp;Later</source>
        <translation>稍后决定(&amp;L)</translation>
    </message>
    <message>
        <source>Decide later; your edits stay unsaved</source>
        <translation>稍后决定；您的修改保持未保存</translation>
    </message>
    <message>
        <source>another station</source>
        <translation>另一工作站</translation>
    </message>
    <message>
        <source>From %1:</source>
        <translation>来自 %1：</translation>
    </message>
    <message>
        <source>From this station:</source>
        <translation>来自本工作站：</translation>
    </message>
    <message>
        <source>Version of T%1 to keep</source>
        <translation>要保留的 T%1 版本</translation>
    </message>
    <message>
        <source>Keep mine</source>
        <translation>保留我的</translation>
    </message>
    <message>
        <source>Take theirs (%1)</source>
        <translation>采用对方的（%1）</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>描述</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>（无）</translation>
    </message>
    <message>
        <source>Pocket</source>
        <translation>刀位</translation>
    </message>
    <message>
        <source>TLO</source>
        <translation>TLO</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>长度</translation>
    </message>
    <message>
        <source>Length wear</source>
        <translation>长度磨损</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>半径</translation>
    </message>
    <message>
        <source>Radius wear</source>
        <translation>半径磨损</translation>
    </message>
    <message>
        <source>Break test</source>
        <translation>断刀检测</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <source>passed or not run</source>
        <translation>通过或未执行</translation>
    </message>
    <message>
        <source>Reference MCS Z</source>
        <translation>基准 MCS Z</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>LinuxCNC fields</source>
        <translation>LinuxCNC 字段</translation>
    </message>
    <message>
        <source>read from the controller</source>
        <translation>从控制器读取</translation>
    </message>
</context>
<context>
    <name>Toffee::ConnectionPanel</name>
    <message>
        <source>Refresh</source>
        <translation>刷新</translation>
    </message>
    <message>
        <source>Machine port</source>
        <translation>机床端口</translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation>波特率</translation>
    </message>
    <message>
        <source>Refresh the list of ports</source>
        <translation>刷新端口列表</translation>
    </message>
    <message>
        <source>Built-in emulator</source>
        <translation>内置模拟器</translation>
    </message>
    <message>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>正在连接…</translation>
    </message>
    <message>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Toffee&apos;s own Carvera, for trying things out</source>
        <translation>Toffee 自带的 Carvera，用于试用</translation>
    </message>
    <message>
        <source>How to reach the machine</source>
        <translation>连接机器的方式</translation>
    </message>
    <message>
        <source>Serial port (USB)</source>
        <translation>串口（USB）</translation>
    </message>
    <message>
        <source>Wi-Fi</source>
        <translation>Wi-Fi</translation>
    </message>
    <message>
        <source>Machine on the network</source>
        <translation>网络中的机器</translation>
    </message>
    <message>
        <source>Address, such as 192.168.1.57</source>
        <translation>地址，例如 192.168.1.57</translation>
    </message>
    <message>
        <source>%1 — %2 (busy)</source>
        <translation>%1 — %2（忙）</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>Cannot connect to the machine</source>
        <translation>无法连接到机床</translation>
    </message>
    <message>
        <source>No machine chosen. Choose one of the machines heard on the network, or type the machine&apos;s address as its screen shows it (such as 192.168.1.57).</source>
        <translation>未选择机器。请选择网络中发现的机器之一，或按机器屏幕显示的地址输入（例如 192.168.1.57）。</translation>
    </message>
    <message>
        <source>The machine is busy</source>
        <translation>机床正忙</translation>
    </message>
    <message>
        <source>%1 says it is busy: another program is connected to it (Makera&apos;s controller, a phone, another computer).</source>
        <translation>%1 表示它正忙：另一个程序已连接到它（Makera 的控制程序、手机或另一台电脑）。</translation>
    </message>
    <message>
        <source>Commands from two programs at once can interfere, and each sees the other&apos;s replies. Disconnect the other program first, or connect anyway.</source>
        <translation>两个程序同时发送命令可能互相干扰，且各自会看到对方的回复。请先断开另一个程序，或仍然连接。</translation>
    </message>
    <message>
        <source>Connect Anyway</source>
        <translation>仍然连接</translation>
    </message>
    <message>
        <source>Cannot listen for machines on UDP port %1 (%2): type the machine&apos;s address.</source>
        <translation>无法在 UDP 端口 %1 上侦听机器（%2）：请输入机器的地址。</translation>
    </message>
    <message>
        <source>%1 is busy: another program is connected to it.</source>
        <translation>%1 正忙：另一个程序已连接到它。</translation>
    </message>
    <message>
        <source>Listening for machines on the network… None heard yet: a Carvera announces itself once a second when its Wi-Fi is on. Or type its address.</source>
        <translation>正在侦听网络中的机器… 尚未发现：Carvera 在 Wi-Fi 开启时每秒广播一次。也可输入它的地址。</translation>
    </message>
    <message>
        <source>One machine heard on the network.</source>
        <translation>在网络中发现一台机器。</translation>
    </message>
    <message>
        <source>%1 machines heard on the network.</source>
        <translation>在网络中发现 %1 台机器。</translation>
    </message>
    <message>
        <source>Controller the machine runs</source>
        <translation>机床所用的控制器</translation>
    </message>
    <message>
        <source>%1 announcements were not listed: a device announced many names (a flood, or a misbehaving device). Every machine announcing itself from its own address is listed.</source>
        <translation>有 %1 条广播未列出：某个设备广播了很多名称（泛洪或设备故障）。凡是从自身地址广播的机器都会列出。</translation>
    </message>
    <message>
        <source>Which controller the machine runs. Automatic asks it with questions that change nothing on a Carvera or on grblHAL; a controller chosen is checked all the same.</source>
        <translation>机器使用的控制器。“自动”会用不会改变 Carvera 或 grblHAL 任何状态的问题询问它；选定的控制器同样会被核对。</translation>
    </message>
    <message>
        <source>Automatic: %1</source>
        <translation>自动：%1</translation>
    </message>
</context>
<context>
    <name>Toffee::ConsoleCheck</name>
    <message>
        <source>The machine is halted: only Unlock ($X) runs now. Check the machine, then use Machine ▸ Unlock.</source>
        <translation>机床已停机：现在只能执行解锁（$X）。请检查机床，然后使用“机床 ▸ 解锁”。</translation>
    </message>
    <message>
        <source>$H homes the machine: every axis moves to its limit switch.</source>
        <translation>$H 使机床回零：每个轴都移动到其限位开关。</translation>
    </message>
    <message>
        <source>%1 jogs the machine.</source>
        <translation>%1 会点动机床。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a G-code line Toffee can read; check it for a letter without a number.</source>
        <translation>“%1”不是 Toffee 能读取的 G 代码行；请检查其中是否有不带数字的字母。</translation>
    </message>
    <message>
        <source>The machine is halted: it refuses &quot;%1&quot; until it is unlocked. Check the machine, then use Machine ▸ Unlock ($X).</source>
        <translation>机床已停机：解锁之前它拒绝执行“%1”。请检查机床，然后使用“机床 ▸ 解锁”（$X）。</translation>
    </message>
    <message>
        <source>M6 needs a tool (M6 T2).</source>
        <translation>M6 需要指定刀具（M6 T2）。</translation>
    </message>
    <message>
        <source>%1 starts the spindle.</source>
        <translation>%1 会启动主轴。</translation>
    </message>
    <message>
        <source>%1 moves the machine.</source>
        <translation>%1 会移动机床。</translation>
    </message>
    <message>
        <source>Toffee asks the machine for its status several times a second: the strip at the top shows it.</source>
        <translation>Toffee 每秒多次向机床查询状态：顶部的状态栏会显示它。</translation>
    </message>
    <message>
        <source>%1 is not a tool number; use %2 to %3 (%4 for an empty spindle).</source>
        <translation>%1 不是刀具号；请使用 %2 到 %3（%4 表示主轴为空）。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a G-code line Toffee can read: %2</source>
        <translation>“%1”不是 Toffee 能读取的 G 代码行：%2</translation>
    </message>
    <message>
        <source>%1 writes an offset into the controller (a tool&apos;s length or a work offset); nothing moves, but the next moves use it.</source>
        <translation>%1 将一个偏置写入控制器（刀具长度或工件偏置）；机器不会移动，但之后的移动会使用它。</translation>
    </message>
    <message>
        <source>%1 shifts the work coordinates; nothing moves, but the next moves use them.</source>
        <translation>%1 平移工件坐标；机器不会移动，但之后的移动会使用它们。</translation>
    </message>
    <message>
        <source>%1 sets the tool length offset in force; nothing moves, but the next moves use it.</source>
        <translation>%1 设置当前生效的刀具长度偏置；机器不会移动，但之后的移动会使用它。</translation>
    </message>
    <message>
        <source>Toffee works in millimetres: after G20 the controller would read every later line in inches while Toffee shows millimetres. Use G21.</source>
        <translation>Toffee 使用毫米：G20 之后，控制器会以英寸读取之后的每一行，而 Toffee 显示的是毫米。请使用 G21。</translation>
    </message>
    <message>
        <source>M6 T%1 changes the tool.</source>
        <translation>M6 T%1 更换刀具。</translation>
    </message>
</context>
<context>
    <name>Toffee::ConsoleDock</name>
    <message>
        <source>Console</source>
        <translation>控制台</translation>
    </message>
    <message>
        <source>Lines sent to and received from the machine</source>
        <translation>发送到机床和从机床接收的各行</translation>
    </message>
    <message>
        <source>Filter the console</source>
        <translation>筛选控制台</translation>
    </message>
    <message>
        <source>Filter…</source>
        <translation>筛选…</translation>
    </message>
    <message>
        <source>Command to send to the machine</source>
        <translation>要发送给机床的命令</translation>
    </message>
    <message>
        <source>not connected; connect first</source>
        <translation>未连接；请先连接</translation>
    </message>
    <message>
        <source>the machine is busy with %1; wait for it</source>
        <translation>机床正忙于 %1；请等待</translation>
    </message>
    <message>
        <source>… (%1 bytes in all)</source>
        <translation>…（共 %1 字节）</translation>
    </message>
    <message>
        <source>not sent: %1</source>
        <translation>未发送：%1</translation>
    </message>
    <message>
        <source>Send %1?</source>
        <translation>发送 %1？</translation>
    </message>
    <message>
        <source>Keep hands clear. Send it?</source>
        <translation>手请远离机床。确定发送吗？</translation>
    </message>
    <message>
        <source>not sent: cancelled</source>
        <translation>未发送：已取消</translation>
    </message>
    <message>
        <source>recorded in the table: T%1 TLO %2, set by hand</source>
        <translation>已记录到刀具表：T%1 TLO %2，手动设置</translation>
    </message>
    <message>
        <source>the TLO is set on the machine but not recorded: %1</source>
        <translation>TLO 已在机床上设置，但未记录：%1</translation>
    </message>
    <message>
        <source>The TLO is %1 now.</source>
        <translation>当前 TLO 为 %1。</translation>
    </message>
    <message>
        <source>T%1 is not in the tool table.</source>
        <translation>T%1 不在刀具表中。</translation>
    </message>
    <message>
        <source>the tool was probed, but its TLO could not be read, so nothing was recorded: %1</source>
        <translation>刀具已对刀，但无法读取其 TLO，因此未记录任何内容：%1</translation>
    </message>
    <message>
        <source>recorded in the table: T%1 TLO %2, probed</source>
        <translation>已记录到刀具表：T%1 TLO %2，已对刀</translation>
    </message>
    <message>
        <source>T%1 was probed but not recorded: %2</source>
        <translation>T%1 已对刀，但未记录：%2</translation>
    </message>
    <message>
        <source>Type a command and press Enter; ↑ ↓ for history</source>
        <translation>输入命令并按回车；↑ ↓ 查看历史</translation>
    </message>
    <message>
        <source>Type a command (e.g. %1) and press Enter; ↑ ↓ for history</source>
        <translation>输入命令（例如 %1）并按回车；↑ ↓ 查看历史</translation>
    </message>
</context>
<context>
    <name>Toffee::ControllerDetector</name>
    <message>
        <source>nothing</source>
        <translation>没有任何内容</translation>
    </message>
    <message>
        <source>Automatic</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>The link to %1 did not open within %2 s. Check the machine and the connection, then try again.</source>
        <translation>与 %1 的连接未能在 %2 秒内打开。请检查机器和连接，然后重试。</translation>
    </message>
    <message>
        <source>%1 The controller was asked which it is (&quot;version&quot;) and did not answer; nothing else was sent.</source>
        <translation>%1 已询问控制器的类型（“version”），但它没有回答；未发送其他任何内容。</translation>
    </message>
    <message>
        <source>The controller answered $I as Grbl does but did not say it is grblHAL ([FIRMWARE:grblHAL]): it may be classic Grbl, which keeps no tool table. Toffee manages Carvera and grblHAL machines; nothing else was sent.</source>
        <translation>控制器像 Grbl 一样回答了 $I，但没有表明自己是 grblHAL（[FIRMWARE:grblHAL]）：它可能是经典 Grbl，不保存刀具表。Toffee 管理 Carvera 和 grblHAL 机器；未发送其他任何内容。</translation>
    </message>
    <message>
        <source>The controller is not a Carvera, grblHAL or LinuxCNC, the controllers Toffee manages: it answered &quot;version&quot; with %1 and &quot;$I&quot; with %2. Nothing else was sent. If it is one of them, choose it (Carvera, grblHAL or LinuxCNC; toffee-cli --controller) and connect again.</source>
        <translation>该控制器不是 Toffee 管理的 Carvera、grblHAL 或 LinuxCNC：它对“version”的回答是 %1，对“$I”的回答是 %2。未发送其他任何内容。如果它确实是其中之一，请选择它（Carvera、grblHAL 或 LinuxCNC；toffee-cli --controller）后重新连接。</translation>
    </message>
    <message>
        <source>%1 The machine answered nothing: not to the Carvera&apos;s and grblHAL&apos;s first question, nor to LinuxCNC&apos;s hello. Check that it is switched on and has started, and the address and port.</source>
        <translation>%1 机床没有任何回应：既没有回答 Carvera 和 grblHAL 的第一个问题，也没有回答 LinuxCNC 的 hello。请检查它是否已开机并启动完成，以及地址和端口。</translation>
    </message>
    <message>
        <source>The controller is none of those Toffee manages: it answered LinuxCNC&apos;s hello with %1. Nothing else was sent.</source>
        <translation>该控制器不是 Toffee 管理的任何一种：它对 LinuxCNC 的 hello 回答了 %1。未发送其他任何内容。</translation>
    </message>
</context>
<context>
    <name>Toffee::EditToolCommand</name>
    <message>
        <source>Edit tool T%1</source>
        <translation>编辑刀具 T%1</translation>
    </message>
</context>
<context>
    <name>Toffee::EmulatorTransport</name>
    <message>
        <source>The link to the emulator dropped.</source>
        <translation>与模拟器的连接已中断。</translation>
    </message>
    <message>
        <source>The link to the emulator is not open.</source>
        <translation>与模拟器的连接未打开。</translation>
    </message>
    <message>
        <source>built-in emulator</source>
        <translation>内置模拟器</translation>
    </message>
</context>
<context>
    <name>Toffee::Error</name>
    <message>
        <source>line %1: %2</source>
        <translation>第 %1 行：%2</translation>
    </message>
</context>
<context>
    <name>Toffee::ExportDialog</name>
    <message>
        <source>Save…</source>
        <translation>保存…</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>复制</translation>
    </message>
    <message>
        <source>Export for Controller</source>
        <translation>为控制器导出</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>刀具</translation>
    </message>
    <message>
        <source>All tools</source>
        <translation>所有刀具</translation>
    </message>
    <message>
        <source>The program that will be written</source>
        <translation>将要写入的程序</translation>
    </message>
    <message>
        <source>Controller:</source>
        <translation>控制器：</translation>
    </message>
    <message>
        <source>Tool:</source>
        <translation>刀具：</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation>无法导出</translation>
    </message>
    <message>
        <source>Save the Offset Program</source>
        <translation>保存补偿程序</translation>
    </message>
    <message>
        <source>G-code programs (*.nc *.ngc *.gcode *.pgm);;All files (*)</source>
        <translation>G 代码程序 (*.nc *.ngc *.gcode *.pgm);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>Toffee::FirmwareInfo</name>
    <message>
        <source>Community firmware %1</source>
        <translation>社区固件 %1</translation>
    </message>
    <message>
        <source>Makera stock firmware %1</source>
        <translation>Makera 原厂固件 %1</translation>
    </message>
    <message>
        <source>grblHAL %1</source>
        <translation>grblHAL %1</translation>
    </message>
    <message>
        <source>Unknown firmware (it did not answer &quot;version&quot;)</source>
        <translation>未知固件（未响应“version”）</translation>
    </message>
    <message>
        <source>Unknown firmware %1</source>
        <translation>未知固件 %1</translation>
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
        <translation>“%1”为 %2，不是对象。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is %2, not text.</source>
        <translation>“%1”为 %2，不是文本。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is %2, not a number.</source>
        <translation>“%1”为 %2，不是数字。</translation>
    </message>
    <message>
        <source>it has no &quot;post-process&quot; &quot;number&quot;: Toffee needs the T number the post writes.</source>
        <translation>它没有“post-process”的“number”：Toffee 需要后处理器输出的 T 号。</translation>
    </message>
    <message>
        <source>its &quot;number&quot; is %1, not a whole number.</source>
        <translation>它的“number”为 %1，不是整数。</translation>
    </message>
    <message>
        <source>its &quot;length-offset&quot; is %1, not a whole number.</source>
        <translation>它的“length-offset”为 %1，不是整数。</translation>
    </message>
    <message>
        <source>its &quot;number&quot; %1 is out of range; use %2 to %3.</source>
        <translation>它的“number” %1 超出范围；请使用 %2 到 %3。</translation>
    </message>
    <message>
        <source>its &quot;unit&quot; is &quot;%1&quot;; Toffee reads millimeters or inches.</source>
        <translation>它的“unit”为“%1”；Toffee 只读取 millimeters 或 inches。</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; appears twice; Toffee will not guess which one is meant.</source>
        <translation>键“%1”出现了两次；Toffee 不会猜测指的是哪一个。</translation>
    </message>
</context>
<context>
    <name>Toffee::GCodeInterpreter</name>
    <message>
        <source>&quot;%1&quot; is not G-code this controller reads.</source>
        <translation>“%1”不是此控制器能读取的 G 代码。</translation>
    </message>
    <message>
        <source>the word %1 needs a value.</source>
        <translation>字 %1 需要一个值。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number.</source>
        <translation>“%1”不是数字。</translation>
    </message>
    <message>
        <source>G%1 is not simulated.</source>
        <translation>不模拟 G%1。</translation>
    </message>
    <message>
        <source>on Automation1, G43 is not tool length compensation; use G44 axes, offsets and G143 / G144.</source>
        <translation>在 Automation1 上，G43 不是刀具长度补偿；请使用 G44 轴、补偿值和 G143 / G144。</translation>
    </message>
    <message>
        <source>G143, G144 and G149 exclude one another.</source>
        <translation>G143、G144 和 G149 互相排斥。</translation>
    </message>
    <message>
        <source>the Carvera has no G43/G44/G49: its TLO always applies.</source>
        <translation>Carvera 没有 G43/G44/G49：其 TLO 始终生效。</translation>
    </message>
    <message>
        <source>PS0030 ILLEGAL OFFSET NUMBER: H%1; offsets go from 0 to %2.</source>
        <translation>PS0030 ILLEGAL OFFSET NUMBER：H%1；补偿号为 0 到 %2。</translation>
    </message>
    <message>
        <source>H%1 is not an offset number (0 to %2).</source>
        <translation>H%1 不是补偿号（0 到 %2）。</translation>
    </message>
    <message>
        <source>Cannot change tool offset with cutter radius compensation on</source>
        <translation>Cannot change tool offset with cutter radius compensation on（刀具半径补偿开启时不能更改刀具补偿）</translation>
    </message>
    <message>
        <source>M61 needs Q, the tool number.</source>
        <translation>M61 需要 Q，即刀具号。</translation>
    </message>
    <message>
        <source>tool %1 is not in the tool table.</source>
        <translation>刀具 %1 不在刀具表中。</translation>
    </message>
    <message>
        <source>G43.1 needs Z, the offset.</source>
        <translation>G43.1 需要 Z，即补偿值。</translation>
    </message>
    <message>
        <source>G43.2 needs H, the tool whose offset it adds.</source>
        <translation>G43.2 需要 H，即要加上其补偿的刀具。</translation>
    </message>
    <message>
        <source>PS0031 ILLEGAL P COMMAND IN G10: G10 needs an L word.</source>
        <translation>PS0031 ILLEGAL P COMMAND IN G10：G10 需要 L 字。</translation>
    </message>
    <message>
        <source>G10 needs an L word.</source>
        <translation>G10 需要 L 字。</translation>
    </message>
    <message>
        <source>G10 L%1 is not simulated for LinuxCNC; G10 L1 writes the tool table.</source>
        <translation>LinuxCNC 不模拟 G10 L%1；G10 L1 写入刀具表。</translation>
    </message>
    <message>
        <source>G10 L1 needs P, a tool number in the tool table.</source>
        <translation>G10 L1 需要 P，即刀具表中的刀具号。</translation>
    </message>
    <message>
        <source>G10 L1: tool %1 is not in the tool table.</source>
        <translation>G10 L1：刀具 %1 不在刀具表中。</translation>
    </message>
    <message>
        <source>this controller&apos;s offset table is not programmed with G10.</source>
        <translation>此控制器的补偿表不是用 G10 编程的。</translation>
    </message>
    <message>
        <source>G10 may not be programmed while cutter compensation (G41/G42) is active; nothing was written.</source>
        <translation>刀具半径补偿（G41/G42）生效时不能编写 G10；未写入任何内容。</translation>
    </message>
    <message>
        <source>PS0031 ILLEGAL P COMMAND IN G10: L%1 is not L10 to L13.</source>
        <translation>PS0031 ILLEGAL P COMMAND IN G10：L%1 不是 L10 到 L13。</translation>
    </message>
    <message>
        <source>G10 L%1 is not L10 to L13.</source>
        <translation>G10 L%1 不是 L10 到 L13。</translation>
    </message>
    <message>
        <source>PS0031 ILLEGAL P COMMAND IN G10: P must be an offset number from 1 to %1.</source>
        <translation>PS0031 ILLEGAL P COMMAND IN G10：P 必须是 1 到 %1 的补偿号。</translation>
    </message>
    <message>
        <source>G10 needs P, an offset number from 1 to %1.</source>
        <translation>G10 需要 P，即 1 到 %1 的补偿号。</translation>
    </message>
    <message>
        <source>PS0031 ILLEGAL P COMMAND IN G10: the value (R) is missing.</source>
        <translation>PS0031 ILLEGAL P COMMAND IN G10：缺少值（R）。</translation>
    </message>
    <message>
        <source>G10 needs R, the value.</source>
        <translation>G10 需要 R，即数值。</translation>
    </message>
    <message>
        <source>PS0032 ILLEGAL OFFSET VALUE IN G10: %1 is beyond ±%2.</source>
        <translation>PS0032 ILLEGAL OFFSET VALUE IN G10：%1 超出 ±%2。</translation>
    </message>
    <message>
        <source>G10: %1 is beyond ±%2.</source>
        <translation>G10：%1 超出 ±%2。</translation>
    </message>
    <message>
        <source>cutter compensation takes 2 or 3 axes.</source>
        <translation>刀具补偿需要 2 或 3 个轴。</translation>
    </message>
    <message>
        <source>the compensation axes can only change while cutter offset compensation is off.</source>
        <translation>只有在刀具偏置补偿关闭时才能更改补偿轴。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a call this simulator knows.</source>
        <translation>“%1”不是此模拟器认识的调用。</translation>
    </message>
    <message>
        <source>CutterCompensationSetAxes takes axes such as [X, Y, Z].</source>
        <translation>CutterCompensationSetAxes 需要轴，例如 [X, Y, Z]。</translation>
    </message>
    <message>
        <source>CutterCompensationSetOffsets works only while cutter offset compensation is off.</source>
        <translation>CutterCompensationSetOffsets 只能在刀具偏置补偿关闭时使用。</translation>
    </message>
    <message>
        <source>CutterCompensationSetOffsets needs %1 offsets, one for each compensation axis.</source>
        <translation>CutterCompensationSetOffsets 需要 %1 个补偿值，每个补偿轴一个。</translation>
    </message>
    <message>
        <source>Home takes axes such as X or [X, Y].</source>
        <translation>Home 需要轴，例如 X 或 [X, Y]。</translation>
    </message>
    <message>
        <source>%1%2 must be a whole number from %3 to %4.</source>
        <translation>%1%2 必须是 %3 到 %4 之间的整数。</translation>
    </message>
    <message>
        <source>too many G codes in one block.</source>
        <translation>一个程序段中的 G 代码太多。</translation>
    </message>
    <message>
        <source>too many M codes in one block.</source>
        <translation>一个程序段中的 M 代码太多。</translation>
    </message>
    <message>
        <source>the word %1 appears twice in one block.</source>
        <translation>字 %1 在一个程序段中出现了两次。</translation>
    </message>
    <message>
        <source>F%1 is not a feed rate.</source>
        <translation>F%1 不是进给速度。</translation>
    </message>
    <message>
        <source>the arc&apos;s R%1 cannot reach its end point.</source>
        <translation>圆弧的 R%1 无法到达其终点。</translation>
    </message>
    <message>
        <source>G%1 needs the arc&apos;s centre (%2 %3) or its radius (R).</source>
        <translation>G%1 需要圆弧的圆心（%2 %3）或半径（R）。</translation>
    </message>
    <message>
        <source>G10 L%1 P%2: the work offsets are G54 to G59 (P1 to P6; LinuxCNC&apos;s G59.1 to G59.3 are P7 to P9).</source>
        <translation>G10 L%1 P%2：工件坐标系为 G54 到 G59（P1 到 P6；LinuxCNC 的 G59.1 到 G59.3 为 P7 到 P9）。</translation>
    </message>
    <message>
        <source>M%1 calls or ends a subprogram, which the check does not follow: what it cuts is not checked.</source>
        <translation>M%1 调用或结束子程序，检查不会跟进子程序：其中的切削不会被检查。</translation>
    </message>
    <message>
        <source>canned cycles are simulated in the XY plane (G17) only.</source>
        <translation>固定循环只在 XY 平面（G17）中模拟。</translation>
    </message>
    <message>
        <source>G%1 needs Z, the bottom of the hole.</source>
        <translation>G%1 需要 Z，即孔底。</translation>
    </message>
</context>
<context>
    <name>Toffee::GCodeLexer</name>
    <message>
        <source>a comment &quot;(&quot; is never closed on this line.</source>
        <translation>本行的注释“(”没有结束。</translation>
    </message>
    <message>
        <source>unexpected &quot;%1&quot;.</source>
        <translation>意外的“%1”。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a number.</source>
        <translation>“%1”不是数字。</translation>
    </message>
    <message>
        <source>%1 is too large: a controller takes at most eight digits before the decimal point.</source>
        <translation>%1 太大：控制器在小数点前最多接受八位数字。</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not G-code this controller reads.</source>
        <translation>“%1”不是此控制器能读取的 G 代码。</translation>
    </message>
    <message>
        <source>unexpected byte 0x%1.</source>
        <translation>意外的字节 0x%1。</translation>
    </message>
</context>
<context>
    <name>Toffee::GrblHal</name>
    <message>
        <source>A limit switch was hit while moving: the machine stopped at once and may have lost its position. Clear the switch, unlock ($X) and home the machine ($H) before going on.</source>
        <translation>移动过程中触发了限位开关：机器已立即停止，可能已丢失位置。请先让限位开关复位，解锁（$X）并回零（$H），然后再继续。</translation>
    </message>
    <message>
        <source>A move would have gone beyond the machine&apos;s travel: nothing moved and the position is kept. Unlock ($X) and check the target (for a probe: the setter&apos;s position and the lowest Z to search to).</source>
        <translation>某次移动将超出机器行程：机器未移动，位置保持不变。请解锁（$X）并检查目标位置（对于探测：对刀仪的位置以及搜索到的最低 Z）。</translation>
    </message>
    <message>
        <source>The controller was reset or stopped while moving: the position may be lost. Unlock ($X) and home the machine ($H) before going on.</source>
        <translation>控制器在移动过程中被复位或停止：位置可能已丢失。请解锁（$X）并回零（$H），然后再继续。</translation>
    </message>
    <message>
        <source>Probe already touching: the probe input was triggered before the probe moved, so nothing was measured. Unlock ($X), then check that the tool is not resting on the setter and that the setter is clean and wired right.</source>
        <translation>探针已处于触发状态：探测移动开始前探针输入已被触发，因此未测得任何数据。请解锁（$X），然后检查刀具没有压在对刀仪上，且对刀仪清洁、接线正确。</translation>
    </message>
    <message>
        <source>Probe found nothing: the tool never touched the setter within the travel allowed, so nothing was measured. Unlock ($X), then check the setter and the tool: the right tool in the spindle, the setter under it, the lowest Z deep enough.</source>
        <translation>探测未触碰：在允许的行程内刀具始终未碰到对刀仪，因此未测得任何数据。请解锁（$X），然后检查对刀仪和刀具：主轴中是正确的刀具，对刀仪位于其下方，最低 Z 足够深。</translation>
    </message>
    <message>
        <source>Homing was interrupted by a reset. Unlock ($X) or home the machine again ($H).</source>
        <translation>回零被复位中断。请解锁（$X）或重新回零（$H）。</translation>
    </message>
    <message>
        <source>Homing stopped because the safety door was opened. Close the door and home again ($H).</source>
        <translation>因安全门被打开，回零已停止。请关闭安全门并重新回零（$H）。</translation>
    </message>
    <message>
        <source>Homing failed: the machine could not move off a limit switch. Check the switch and its wiring (or the pull-off distance), then home again ($H).</source>
        <translation>回零失败：机器无法离开限位开关。请检查该开关及其接线（或回退距离），然后重新回零（$H）。</translation>
    </message>
    <message>
        <source>Homing failed: a limit switch was not found within the search distance. Check the switches and their wiring, then home again ($H).</source>
        <translation>回零失败：在搜索距离内未找到限位开关。请检查限位开关及其接线，然后重新回零（$H）。</translation>
    </message>
    <message>
        <source>The emergency stop is engaged. Make the machine safe, release the stop, then reset the controller and unlock ($X).</source>
        <translation>急停已触发。请确保机器处于安全状态，释放急停，然后复位控制器并解锁（$X）。</translation>
    </message>
    <message>
        <source>The machine must be homed before it moves: home it ($H).</source>
        <translation>机器在移动前必须先回零：请回零（$H）。</translation>
    </message>
    <message>
        <source>A limit switch is pressed. Unlock ($X), move the machine off the switch, then go on.</source>
        <translation>有限位开关处于触发状态。请解锁（$X），将机器移离该开关，然后继续。</translation>
    </message>
    <message>
        <source>The probe&apos;s protection tripped: the probe was touched while the machine moved. Check the probe, then unlock ($X).</source>
        <translation>探针保护已触发：机器移动时探针被触碰。请检查探针，然后解锁（$X）。</translation>
    </message>
    <message>
        <source>The spindle did not reach its speed in time. Check the spindle and its drive, then unlock ($X).</source>
        <translation>主轴未能及时达到设定转速。请检查主轴及其驱动器，然后解锁（$X）。</translation>
    </message>
    <message>
        <source>The controller&apos;s power-on self test failed. Switch the controller off and on; if it happens again, check its wiring.</source>
        <translation>控制器上电自检失败。请将控制器断电后重新上电；如果再次出现，请检查其接线。</translation>
    </message>
    <message>
        <source>A motor driver reported a fault. Check the drivers and the motors, then reset the controller.</source>
        <translation>某个电机驱动器报告了故障。请检查驱动器和电机，然后复位控制器。</translation>
    </message>
    <message>
        <source>Homing failed: the homing settings do not fit the machine. Check them ($$), then home again ($H).</source>
        <translation>回零失败：回零设置与机器不符。请检查这些设置（$$），然后重新回零（$H）。</translation>
    </message>
    <message>
        <source>A Modbus device (often the spindle&apos;s drive) did not answer or answered wrong. Check its cable and settings, then reset the controller.</source>
        <translation>某个 Modbus 设备（通常是主轴驱动器）无应答或应答错误。请检查其线缆和设置，然后复位控制器。</translation>
    </message>
    <message>
        <source>The controller lost contact with an input/output expander. Check it and its cable, then reset the controller.</source>
        <translation>控制器与输入/输出扩展模块失去联系。请检查该模块及其线缆，然后复位控制器。</translation>
    </message>
    <message>
        <source>The controller&apos;s settings memory failed: its settings and tool table may be lost. Check them ($$ and $#) before going on.</source>
        <translation>控制器的设置存储器出错：其设置和刀具表可能已丢失。请先检查（$$ 和 $#）再继续。</translation>
    </message>
    <message>
        <source>The controller&apos;s buffer overflowed. Reset the controller and send the work again.</source>
        <translation>控制器缓冲区溢出。请复位控制器并重新发送加工任务。</translation>
    </message>
    <message>
        <source>The controller halted (ALARM:%1). Make the machine safe, then unlock ($X) or reset the controller; the controller&apos;s documentation says what this alarm means.</source>
        <translation>控制器已停机（ALARM:%1）。请确保机器处于安全状态，然后解锁（$X）或复位控制器；该报警的含义请参阅控制器文档。</translation>
    </message>
    <message>
        <source>The controller could not read a word of the line (a letter and a number each). Check the line.</source>
        <translation>控制器无法读取该行中的某个字（每个字由一个字母和一个数字组成）。请检查该行。</translation>
    </message>
    <message>
        <source>The controller does not know this $ command.</source>
        <translation>控制器不认识此 $ 命令。</translation>
    </message>
    <message>
        <source>The controller takes this $ command only while idle: wait for the machine to stop, then try again.</source>
        <translation>控制器仅在空闲时接受此 $ 命令：请等待机器停止，然后重试。</translation>
    </message>
    <message>
        <source>G-code locked out during alarm or jog state: the controller is halted. Find out why it halted, unlock ($X), then try again.</source>
        <translation>在报警或点动状态下 G 代码被锁定：控制器已停机。请查明停机原因，解锁（$X），然后重试。</translation>
    </message>
    <message>
        <source>The line is too long for the controller; it was not carried out.</source>
        <translation>该行对控制器而言过长；未被执行。</translation>
    </message>
    <message>
        <source>The safety door is open. Close it and go on.</source>
        <translation>安全门已打开。请关闭安全门后继续。</translation>
    </message>
    <message>
        <source>The jog would go beyond the machine&apos;s travel; the machine did not move.</source>
        <translation>点动将超出机器行程；机器未移动。</translation>
    </message>
    <message>
        <source>The controller was reset; the line was not carried out.</source>
        <translation>控制器已复位；该行未被执行。</translation>
    </message>
    <message>
        <source>The controller does not support a command in the line (or the command is not valid there).</source>
        <translation>控制器不支持该行中的某个命令（或该命令在此处无效）。</translation>
    </message>
    <message>
        <source>The line holds words that cannot go together. Check the line.</source>
        <translation>该行包含不能同时使用的字。请检查该行。</translation>
    </message>
    <message>
        <source>No feed rate is set for the move: give one with F.</source>
        <translation>该移动未设置进给速度：请用 F 指定。</translation>
    </message>
    <message>
        <source>A command in the line lacks a value or needs a whole number. Check the line.</source>
        <translation>该行中的某个命令缺少数值或需要整数。请检查该行。</translation>
    </message>
    <message>
        <source>The move has no valid target. Check its axis words.</source>
        <translation>该移动没有有效的目标位置。请检查其轴字。</translation>
    </message>
    <message>
        <source>G43.1 was given for an axis that is not the controller&apos;s tool length axis (Z).</source>
        <translation>G43.1 指定的轴不是控制器的刀长轴（Z）。</translation>
    </message>
    <message>
        <source>No such tool in the controller: the number is beyond its tool table, or the tool is not in it. Check the table&apos;s size ($I) and the tool&apos;s number.</source>
        <translation>控制器中没有此刀具：编号超出其刀具表范围，或刀具表中没有该刀具。请检查刀具表大小（$I）和刀具编号。</translation>
    </message>
    <message>
        <source>A value in the line is out of the range the controller takes.</source>
        <translation>该行中的某个数值超出了控制器接受的范围。</translation>
    </message>
    <message>
        <source>A tool change is waiting to be finished: finish it (cycle start) before sending more.</source>
        <translation>有换刀操作等待完成：请先完成换刀（循环启动），再发送后续内容。</translation>
    </message>
    <message>
        <source>A limit switch is pressed: only homing is allowed. Move off the switch or home ($H).</source>
        <translation>有限位开关处于触发状态：只允许回零。请移离该开关或回零（$H）。</translation>
    </message>
    <message>
        <source>The machine must be homed first: home it ($H).</source>
        <translation>机器必须先回零：请回零（$H）。</translation>
    </message>
    <message>
        <source>The controller does not know which tool is in the spindle: tell it with M61 Q&lt;n&gt;.</source>
        <translation>控制器不知道主轴中是哪把刀具：请用 M61 Q&lt;n&gt; 告知。</translation>
    </message>
    <message>
        <source>The controller&apos;s power-on self test failed: switch it off and on.</source>
        <translation>控制器上电自检失败：请将其断电后重新上电。</translation>
    </message>
    <message>
        <source>The emergency stop is engaged. Release it and reset the controller.</source>
        <translation>急停已触发。请释放急停并复位控制器。</translation>
    </message>
    <message>
        <source>Not allowed while a critical event is active (an emergency stop, a hard limit or a motor fault). Clear it and reset the controller.</source>
        <translation>存在严重事件（急停、硬限位或电机故障）时不允许此操作。请排除该事件并复位控制器。</translation>
    </message>
    <message>
        <source>There is already a tool in the spindle: remove it first.</source>
        <translation>主轴中已有刀具：请先将其取下。</translation>
    </message>
    <message>
        <source>There is no tool in the spindle: put one in (or tell the controller with M61 Q&lt;n&gt;).</source>
        <translation>主轴中没有刀具：请装入一把刀具（或用 M61 Q&lt;n&gt; 告知控制器）。</translation>
    </message>
    <message>
        <source>The controller refused the line (error:%1).</source>
        <translation>控制器拒绝了该行（error:%1）。</translation>
    </message>
</context>
<context>
    <name>Toffee::GrblHalController</name>
    <message>
        <source>grblHAL answered $G without its modal state ([GC:…]); is this grblHAL?</source>
        <translation>grblHAL 对 $G 的应答中没有模态状态（[GC:…]）；这是 grblHAL 吗？</translation>
    </message>
    <message>
        <source>The machine answered but sent no status report when asked; is it grblHAL? If it is a Carvera, choose the Carvera (--controller carvera).</source>
        <translation>机床有应答，但在询问时没有发送状态报告；它是 grblHAL 吗？如果是 Carvera，请选择 Carvera（--controller carvera）。</translation>
    </message>
    <message>
        <source>This controller answered $I as Grbl does but did not say it is grblHAL ([FIRMWARE:grblHAL]); it may be classic Grbl, which keeps no tool table. Toffee manages grblHAL and the Carvera.</source>
        <translation>该控制器像 Grbl 一样应答了 $I，但没有表明自己是 grblHAL（[FIRMWARE:grblHAL]）；它可能是经典 Grbl，不保存刀具表。Toffee 管理的是 grblHAL 和 Carvera。</translation>
    </message>
    <message>
        <source>This machine did not answer $I as grblHAL does. If it is a Carvera, connect with the Carvera chosen (--controller carvera).</source>
        <translation>该机床没有像 grblHAL 那样应答 $I。如果是 Carvera，请选择 Carvera 后再连接（--controller carvera）。</translation>
    </message>
    <message>
        <source>grblHAL sent no status report within 2 s.</source>
        <translation>grblHAL 在 2 秒内没有发送状态报告。</translation>
    </message>
    <message>
        <source>grblHAL says no tool is in the spindle (T0), so there is nothing to %1. Say which tool is in (Select Tool, M61 Q&lt;n&gt;) first.</source>
        <translation>grblHAL 报告主轴中没有刀具（T0），因此无法%1。请先指明装的是哪把刀具（选择刀具，M61 Q&lt;n&gt;）。</translation>
    </message>
    <message>
        <source>Toffee does not know where this machine&apos;s tool setter is. Set it first (Machine ▸ Tool Setter…, or toffee-cli --setter X,Y,ZMIN in machine coordinates).</source>
        <translation>Toffee 不知道这台机床的对刀仪在哪里。请先设置（机床 ▸ 对刀仪…，或用 toffee-cli --setter X,Y,ZMIN 以机床坐标指定）。</translation>
    </message>
    <message>
        <source>The probe did not report a touch. Nothing was measured.</source>
        <translation>探针没有报告触碰。未测得任何数据。</translation>
    </message>
    <message>
        <source>the offset in force reads %1 mm</source>
        <translation>生效的补偿读数为 %1 mm</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>无</translation>
    </message>
    <message>
        <source>T%1&apos;s entry reads %2 mm</source>
        <translation>T%1 的条目读数为 %2 mm</translation>
    </message>
    <message>
        <source>grblHAL was given T%1&apos;s TLO %2 mm, but read back %3. Nothing was recorded; check the controller&apos;s offsets ($#) before you cut.</source>
        <translation>已将 T%1 的 TLO %2 mm 写入 grblHAL，但读回的结果是：%3。未记录任何内容；切削前请检查控制器的补偿（$#）。</translation>
    </message>
    <message>
        <source>T%1 is beyond grblHAL&apos;s table of %2 tools: its TLO is in force (G43.1) but not stored in the controller.</source>
        <translation>T%1 超出了 grblHAL 的刀具表（共 %2 把刀具）：其 TLO 已生效（G43.1），但未保存在控制器中。</translation>
    </message>
    <message>
        <source>This grblHAL keeps no tool table: the TLO is in force (G43.1) until a reset.</source>
        <translation>此 grblHAL 不保存刀具表：TLO 在复位之前一直生效（G43.1）。</translation>
    </message>
    <message>
        <source>measure</source>
        <translation>测量</translation>
    </message>
    <message>
        <source>break-test</source>
        <translation>进行断刀检测</translation>
    </message>
    <message>
        <source>The TLO</source>
        <translation>TLO</translation>
    </message>
    <message>
        <source>set a TLO for</source>
        <translation>设置 TLO</translation>
    </message>
    <message>
        <source>The height above Z0</source>
        <translation>Z0 以上的高度</translation>
    </message>
    <message>
        <source>grblHAL sent no status report, so the tool&apos;s height is not known.</source>
        <translation>grblHAL 没有发送状态报告，因此不知道刀具的高度。</translation>
    </message>
    <message>
        <source>grblHAL was told T%1 is in the spindle but reports T%2.</source>
        <translation>已告知 grblHAL 主轴中是 T%1，但它报告的是 T%2。</translation>
    </message>
    <message>
        <source>grblHAL changes to a tool, not to an empty spindle: use Select Tool with T0.</source>
        <translation>grblHAL 只能换到某把刀具，不能换成空主轴：请使用“选择刀具”并选 T0。</translation>
    </message>
    <message>
        <source>A TLO is restored for a tool, not for an empty spindle.</source>
        <translation>TLO 只能为刀具恢复，不能为空主轴恢复。</translation>
    </message>
    <message>
        <source>%1 (the TLO that puts the tip %2 mm above Z0, from where it is)</source>
        <translation>%1（以当前位置为准，使刀尖位于 Z0 以上 %2 mm 的 TLO）</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO</source>
        <translation>T%1 的 TLO</translation>
    </message>
    <message>
        <source>grblHAL&apos;s table holds T1 to T%1; %2 cannot be written. Nothing was written: renumber them or leave them out.</source>
        <translation>grblHAL 的刀具表只容纳 T1 到 T%1；%2 无法写入。未写入任何内容：请为它们重新编号，或将其略去。</translation>
    </message>
    <message>
        <source>T%1 reads %2 mm, not %3 mm</source>
        <translation>T%1 读数为 %2 mm，而不是 %3 mm</translation>
    </message>
    <message>
        <source>grblHAL&apos;s table does not read back as written: %1.</source>
        <translation>grblHAL 的刀具表读回的值与写入的不符：%1。</translation>
    </message>
    <message>
        <source>grblHAL&apos;s offsets ($#) could not be read whole: lines were malformed or repeated (%1). Nothing was changed; check the connection and try again.</source>
        <translation>无法完整读取 grblHAL 的补偿（$#）：有行格式错误或重复（%1）。未做任何更改；请检查连接后重试。</translation>
    </message>
    <message>
        <source>T%1 is put in by hand (grblHAL&apos;s manual tool change)</source>
        <translation>T%1 需手动装入（grblHAL 的手动换刀）</translation>
    </message>
    <message>
        <source>grblHAL stopped reporting its state during the change to T%1.</source>
        <translation>换到 T%1 期间，grblHAL 停止报告其状态。</translation>
    </message>
    <message>
        <source>grblHAL went into alarm during the change to T%1: nothing was measured.</source>
        <translation>换到 T%1 期间 grblHAL 进入报警：未进行任何测量。</translation>
    </message>
    <message>
        <source>grblHAL was reset to end it: its tool is still T%1, with no offset in force. Check what is in the spindle, then select it and restore or probe its TLO before cutting.</source>
        <translation>已复位 grblHAL 以结束换刀：其刀具仍为 T%1，且无生效的补偿。请检查主轴中的刀具，然后选择它，并在切削前恢复或测量其刀长补偿。</translation>
    </message>
    <message>
        <source>grblHAL is in inches (G20), where its G10 and G38.2 take inches. Toffee %1 in millimetres: send G21, then try again. Nothing was sent.</source>
        <translation>grblHAL 处于英寸模式（G20），此时其 G10 和 G38.2 以英寸计。Toffee 以毫米%1：请发送 G21 后重试。未发送任何内容。</translation>
    </message>
    <message>
        <source>grblHAL reports in inches ($13=1); Toffee reads millimetres. Set $13=0 (reports in millimetres), then connect again.</source>
        <translation>grblHAL 以英寸报告（$13=1）；Toffee 读取毫米。请设置 $13=0（以毫米报告），然后重新连接。</translation>
    </message>
    <message>
        <source>probes</source>
        <translation>测量</translation>
    </message>
    <message>
        <source>writes TLOs</source>
        <translation>写入刀长补偿</translation>
    </message>
    <message>
        <source>writes its table</source>
        <translation>写入其刀具表</translation>
    </message>
    <message>
        <source>grblHAL reported the contact at machine Z %1 mm, outside the search from %2 to %3 mm. Nothing was written or recorded; check the tool setter&apos;s settings and the machine.</source>
        <translation>grblHAL 报告的接触点在机床 Z %1 mm，位于 %2 至 %3 mm 的搜索范围之外。未写入也未记录任何内容；请检查对刀仪设置和机器。</translation>
    </message>
    <message>
        <source>Nothing was written to grblHAL or recorded.</source>
        <translation>未写入 grblHAL，也未记录任何内容。</translation>
    </message>
    <message>
        <source>A jog moves at most %1 mm along each axis, at 1 to %2 mm/min. Nothing was sent.</source>
        <translation>点动每轴最多移动 %1 mm，速度 1 至 %2 mm/min。未发送任何内容。</translation>
    </message>
    <message>
        <source>A jog of 0 mm moves nothing. Nothing was sent.</source>
        <translation>0 mm 的点动不会移动。未发送任何内容。</translation>
    </message>
    <message>
        <source>grblHAL stopped reporting its state while it jogged.</source>
        <translation>grblHAL 在点动时停止报告其状态。</translation>
    </message>
    <message>
        <source>grblHAL went into alarm while it jogged: check the machine, then Unlock.</source>
        <translation>grblHAL 在点动时进入报警：请检查机器，然后解锁。</translation>
    </message>
    <message>
        <source>The jog was stopped where the machine stands; it is ready (no alarm).</source>
        <translation>点动已在机床当前位置停止；机床处于就绪状态（无报警）。</translation>
    </message>
    <message>
        <source>T%1 cannot be probed so: %2 Nothing was sent.</source>
        <translation>T%1 无法这样测量：%2 未发送任何内容。</translation>
    </message>
</context>
<context>
    <name>Toffee::GuideDialog</name>
    <message>
        <source>Toffee&apos;s User&apos;s Guide</source>
        <translation>Toffee 用户指南</translation>
    </message>
    <message>
        <source>%1 is not installed with Toffee: it is in the docs folder of Toffee&apos;s source.</source>
        <translation>%1 未随 Toffee 安装：它位于 Toffee 源代码的 docs 文件夹中。</translation>
    </message>
    <message>
        <source>The user&apos;s guide is missing</source>
        <translation>缺少用户指南</translation>
    </message>
    <message>
        <source>The user&apos;s guide is not where Toffee installs it (%1). Reinstall Toffee&apos;s package, or read docs/GUIDE.md in its source.</source>
        <translation>用户指南不在 Toffee 安装它的位置（%1）。请重新安装 Toffee 软件包，或阅读其源代码中的 docs/GUIDE.md。</translation>
    </message>
</context>
<context>
    <name>Toffee::HistoryDock</name>
    <message>
        <source>probe</source>
        <translation>探测</translation>
    </message>
    <message>
        <source>break test</source>
        <translation>断刀检测</translation>
    </message>
    <message>
        <source>set by hand</source>
        <translation>手动设置</translation>
    </message>
    <message>
        <source>restored</source>
        <translation>已恢复</translation>
    </message>
    <message>
        <source>History</source>
        <translation>历史</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>导出 CSV…</translation>
    </message>
    <message>
        <source>Copy Chart</source>
        <translation>复制图表</translation>
    </message>
    <message>
        <source>TLO over time</source>
        <translation>TLO 随时间变化</translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation>测量记录</translation>
    </message>
    <message>
        <source>Select one tool to see its history.</source>
        <translation>选择一把刀具以查看其历史。</translation>
    </message>
    <message>
        <source>T%1: the history library is not open.</source>
        <translation>T%1：历史库未打开。</translation>
    </message>
    <message>
        <source>T%1 on %2: 1 measurement</source>
        <translation>%2 上的 T%1：1 次测量</translation>
    </message>
    <message>
        <source>T%1 on %2: %3 measurements</source>
        <translation>%2 上的 T%1：%3 次测量</translation>
    </message>
    <message>
        <source>Probes</source>
        <translation>探测</translation>
    </message>
    <message>
        <source>Break test passed</source>
        <translation>断刀检测通过</translation>
    </message>
    <message>
        <source>Break test failed</source>
        <translation>断刀检测未通过</translation>
    </message>
    <message>
        <source>Set by hand</source>
        <translation>手动设置</translation>
    </message>
    <message>
        <source>Wear trend</source>
        <translation>磨损趋势</translation>
    </message>
    <message>
        <source>± %1 mm</source>
        <translation>± %1 mm</translation>
    </message>
    <message>
        <source>No measurements of T%1 yet</source>
        <translation>尚无 T%1 的测量记录</translation>
    </message>
    <message>
        <source>TLO (mm)</source>
        <translation>TLO（mm）</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>类型</translation>
    </message>
    <message>
        <source>TLO</source>
        <translation>TLO</translation>
    </message>
    <message>
        <source>Reference Z</source>
        <translation>参考 Z</translation>
    </message>
    <message>
        <source>Current Z</source>
        <translation>当前 Z</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>公差</translation>
    </message>
    <message>
        <source>Old TLO</source>
        <translation>旧 TLO</translation>
    </message>
    <message>
        <source>New TLO</source>
        <translation>新 TLO</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>BROKEN?</source>
        <translation>断刀？</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>通过</translation>
    </message>
    <message>
        <source>The chart cannot be drawn: Toffee&apos;s chart module %1 is missing. Reinstall Toffee; the measurements are in the table below.</source>
        <translation>无法绘制图表：Toffee 的图表模块 %1 缺失。请重新安装 Toffee；测量值见下方表格。</translation>
    </message>
    <message>
        <source>The chart cannot be drawn: Toffee&apos;s chart module %1 cannot be loaded (%2). Reinstall Toffee; the measurements are in the table below.</source>
        <translation>无法绘制图表：无法加载 Toffee 的图表模块 %1（%2）。请重新安装 Toffee；测量值见下方表格。</translation>
    </message>
    <message>
        <source>read in</source>
        <translation>已读入</translation>
    </message>
    <message>
        <source>new cutter (old one ended)</source>
        <translation>新刀具（旧刀具已结束）</translation>
    </message>
    <message>
        <source>Old cutter</source>
        <translation>旧刀具</translation>
    </message>
    <message>
        <source>Spread</source>
        <translation>差值</translation>
    </message>
    <message>
        <source>%1 touches, at machine Z %2 mm: the TLO is the highest&apos;s (the longest edge)</source>
        <translation>%1 次触碰，机床 Z 为 %2 mm：TLO 取最高一次（最长的刃）</translation>
    </message>
    <message>
        <source>Each edge</source>
        <translation>各刃</translation>
    </message>
</context>
<context>
    <name>Toffee::HistoryRecorder</name>
    <message>
        <source>The library (%1) cannot be reached: its server stopped answering. Toffee keeps what you record and writes it when the server is back.</source>
        <translation>无法连接刀具库（%1）：其服务器已停止响应。Toffee 会保留您记录的内容，待服务器恢复后再写入。</translation>
    </message>
</context>
<context>
    <name>Toffee::HistorySettingsDialog</name>
    <message>
        <source>History Library</source>
        <translation>历史库</translation>
    </message>
    <message>
        <source>Machine name</source>
        <translation>机器名称</translation>
    </message>
    <message>
        <source> days</source>
        <translation> 天</translation>
    </message>
    <message>
        <source>Stale after</source>
        <translation>过期时间</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <source>This machine&apos;s name:</source>
        <translation>本机名称：</translation>
    </message>
    <message>
        <source>A measurement is stale after:</source>
        <translation>测量结果过期时间：</translation>
    </message>
    <message>
        <source>SQLite libraries (*.sqlite *.db);;All files (*)</source>
        <translation>SQLite 库 (*.sqlite *.db);;所有文件 (*)</translation>
    </message>
    <message>
        <source>This library cannot be used: %1</source>
        <translation>无法使用此库：%1</translation>
    </message>
    <message>
        <source>Library file or URL</source>
        <translation>库文件或 URL</translation>
    </message>
    <message>
        <source>A file, or postgresql://user@server/database</source>
        <translation>文件，或 postgresql://user@server/database</translation>
    </message>
    <message>
        <source>An SQLite file for this computer, or a shared PostgreSQL database as postgresql://user@host:port/dbname?sslmode=require. The password goes in the PostgreSQL password file (~/.pgpass), never in the URL.</source>
        <translation>本机使用的 SQLite 文件，或共享的 PostgreSQL 数据库，写作 postgresql://user@host:port/dbname?sslmode=require。密码放在 PostgreSQL 密码文件（~/.pgpass）中，绝不写在 URL 里。</translation>
    </message>
    <message>
        <source>Choose a library file</source>
        <translation>选择库文件</translation>
    </message>
    <message>
        <source>Library file or URL:</source>
        <translation>库文件或 URL：</translation>
    </message>
    <message>
        <source>This station&apos;s name</source>
        <translation>本工作站的名称</translation>
    </message>
    <message>
        <source>Who this computer&apos;s changes are from in a shared library, as the other stations see it; empty: the computer&apos;s name.</source>
        <translation>在共享库中，其他工作站看到的本计算机所做更改的来源；留空则为计算机名。</translation>
    </message>
    <message>
        <source>This station&apos;s name:</source>
        <translation>本工作站的名称：</translation>
    </message>
    <message>
        <source>Its kind: Carvera, grblHAL or Emulator</source>
        <translation>其类型：Carvera、grblHAL 或 Emulator</translation>
    </message>
    <message>
        <source>The name this machine&apos;s history, reference and tool setter are kept under. Left empty, the machine is called after its kind. A name stands for one machine: another machine under it is asked about.</source>
        <translation>保存这台机器的历史、参考和对刀仪的名称。留空时，机器以其类型命名。一个名称只代表一台机器：其他机器使用该名称时会询问。</translation>
    </message>
</context>
<context>
    <name>Toffee::HsmReader</name>
    <message>
        <source>there is no XML element in it</source>
        <translation>其中没有 XML 元素</translation>
    </message>
    <message>
        <source>column %1: this is not an HSM tool library: its root element is &lt;%2&gt; in namespace &quot;%3&quot;, where a library has &lt;tool-library&gt; in &quot;%4&quot;.</source>
        <translation>第 %1 列：这不是 HSM 刀具库：其根元素是命名空间“%3”中的 &lt;%2&gt;，而刀具库的根元素是“%4”中的 &lt;tool-library&gt;。</translation>
    </message>
    <message>
        <source>column %1: this is not well-formed XML (%2).</source>
        <translation>第 %1 列：这不是格式正确的 XML（%2）。</translation>
    </message>
    <message>
        <source>tool %1</source>
        <translation>第 %1 把刀具</translation>
    </message>
    <message>
        <source>its unit is &quot;%1&quot;; Toffee reads millimeters or inches.</source>
        <translation>它的单位为“%1”；Toffee 只读取 millimeters 或 inches。</translation>
    </message>
    <message>
        <source>it has no &lt;nc number=…&gt;: Toffee needs the T number the post writes.</source>
        <translation>它没有 &lt;nc number=…&gt;：Toffee 需要后处理器输出的 T 号。</translation>
    </message>
    <message>
        <source>its nc number is &quot;%1&quot;, not a tool number.</source>
        <translation>它的 nc 编号为“%1”，不是刀具号。</translation>
    </message>
    <message>
        <source>it has a second &lt;%1&gt; (the first is on line %2); a tool has one, and Toffee will not guess which one is meant.</source>
        <translation>它有第二个 &lt;%1&gt;（第一个在第 %2 行）；一个刀具只有一个，Toffee 不会猜测指的是哪一个。</translation>
    </message>
    <message>
        <source>its nc length-offset is &quot;%1&quot;, not a whole number.</source>
        <translation>它的 nc length-offset 为“%1”，不是整数。</translation>
    </message>
    <message>
        <source>its body %1 is &quot;%2&quot;, not a number.</source>
        <translation>它的 body %1 为“%2”，不是数字。</translation>
    </message>
</context>
<context>
    <name>Toffee::ImportPreview</name>
    <message>
        <source>flute length</source>
        <translation>刃长</translation>
    </message>
    <message>
        <source>below the holder</source>
        <translation>夹头下方</translation>
    </message>
    <message>
        <source>overall length</source>
        <translation>总长</translation>
    </message>
    <message>
        <source>description “%1” → “%2”</source>
        <translation>描述“%1”→“%2”</translation>
    </message>
    <message>
        <source>radius %1 → %2 %3</source>
        <translation>半径 %1 → %2 %3</translation>
    </message>
    <message>
        <source>pocket %1; no tool length yet (0 in the table): measure it before use</source>
        <translation>刀位 %1；尚无刀具长度（表中为 0）：使用前请先测量</translation>
    </message>
    <message>
        <source>the library gives length offset H%1; Toffee always uses H = T (H%2), so it is not imported</source>
        <translation>刀具库给出长度补偿 H%1；Toffee 始终使用 H = T（H%2），因此不导入它</translation>
    </message>
    <message>
        <source>CAM lengths added to the notes (%1)</source>
        <translation>CAM 长度已加入备注（%1）</translation>
    </message>
    <message>
        <source>CAM lengths in the notes: %1 → %2</source>
        <translation>备注中的 CAM 长度：%1 → %2</translation>
    </message>
    <message>
        <source>T%1 is in the library twice.</source>
        <translation>T%1 在刀具库中出现了两次。</translation>
    </message>
    <message>
        <source>the CAM lengths line in the notes</source>
        <translation>备注中的 CAM 长度行</translation>
    </message>
    <message>
        <source>%1 new, %2 changed, %3 unchanged</source>
        <translation>新增 %1，修改 %2，未变 %3</translation>
    </message>
    <message>
        <source>type “%1” → “%2”</source>
        <translation>类型“%1”→“%2”</translation>
    </message>
    <message>
        <source>diameter %1 → %2 %3</source>
        <translation>直径 %1 → %2 %3</translation>
    </message>
    <message>
        <source>overall length %1 → %2 %3</source>
        <translation>总长 %1 → %2 %3</translation>
    </message>
    <message>
        <source>the library gives no unit: its lengths are read in %1, as you said</source>
        <translation>刀具库未给出单位：按您的选择以%1读取其长度</translation>
    </message>
    <message>
        <source>inches</source>
        <translation>英寸</translation>
    </message>
    <message>
        <source>millimetres</source>
        <translation>毫米</translation>
    </message>
    <message>
        <source>%1; a new cutter in %2 (measure before use)</source>
        <translation>%1；%2 把为新刀具（使用前请测量）</translation>
    </message>
    <message>
        <source>Tools in this library without &quot;unit&quot; (millimeters or inches): %1. Their diameters and lengths cannot be read. Fusion writes one on every tool: export the library from Fusion again, or add &quot;unit&quot;: &quot;millimeters&quot; (or &quot;inches&quot;) to each, or say which unit they are in (the window asks; toffee-cli import --cam-units mm|in).</source>
        <translation>此库中没有 &quot;unit&quot;（millimeters 或 inches）的刀具：%1。无法读取其直径和长度。Fusion 会为每把刀具写入该项：请从 Fusion 重新导出刀具库，或为每把刀具添加 &quot;unit&quot;: &quot;millimeters&quot;（或 &quot;inches&quot;），或说明它们使用的单位（窗口会询问；toffee-cli import --cam-units mm|in）。</translation>
    </message>
    <message>
        <source>a new cutter (%1): the old cutter&apos;s TLO %2 %3, its length, wear and break mark end; measure it before it cuts</source>
        <translation>新刀具（%1）：旧刀具的 TLO %2 %3、其长度、磨损和断刀标记作废；切削前请先测量</translation>
    </message>
    <message>
        <source>a new cutter (%1): the old cutter&apos;s length, wear and break mark end; measure it before it cuts</source>
        <translation>新刀具（%1）：旧刀具的长度、磨损和断刀标记作废；切削前请先测量</translation>
    </message>
</context>
<context>
    <name>Toffee::ImportPreviewDialog</name>
    <message>
        <source>New</source>
        <translation>新增</translation>
    </message>
    <message>
        <source>Changed</source>
        <translation>修改</translation>
    </message>
    <message>
        <source>Unchanged</source>
        <translation>未变</translation>
    </message>
    <message>
        <source>&amp;Import</source>
        <translation>导入(&amp;I)</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Import tools</source>
        <translation>导入刀具</translation>
    </message>
    <message>
        <source>Import Tools from %1</source>
        <translation>从 %1 导入刀具</translation>
    </message>
    <message>
        <source>What the import does</source>
        <translation>导入将做什么</translation>
    </message>
    <message>
        <source>%1 (%2): %3.</source>
        <translation>%1（%2）：%3。</translation>
    </message>
    <message>
        <source>Only descriptions, radii and the CAM&apos;s line in the notes change; measured TLOs, wear, pockets and your notes stay as they are.</source>
        <translation>只有描述、半径和备注中的 CAM 行会改变；测得的刀长补偿、磨损、刀位和您的备注保持不变。</translation>
    </message>
    <message>
        <source>The table already has these tools as the library describes them.</source>
        <translation>刀具表中已有这些刀具，且与刀具库的描述一致。</translation>
    </message>
    <message>
        <source>Tools in the library</source>
        <translation>刀具库中的刀具</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>刀具</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>导入</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>描述</translation>
    </message>
    <message>
        <source>Changes</source>
        <translation>更改</translation>
    </message>
    <message>
        <source>Changes and notes of the selected tool</source>
        <translation>所选刀具的更改和说明</translation>
    </message>
    <message>
        <source>T%1 (%2): %3</source>
        <translation>T%1（%2）：%3</translation>
    </message>
    <message>
        <source>The table already has this tool as the library describes it.</source>
        <translation>表中已有此刀具，与刀具库的描述一致。</translation>
    </message>
    <message>
        <source>Import the tools</source>
        <translation>导入这些刀具</translation>
    </message>
    <message>
        <source>Cancel the import</source>
        <translation>取消导入</translation>
    </message>
    <message>
        <source>Import or cancel</source>
        <translation>导入或取消</translation>
    </message>
    <message>
        <source>Only descriptions, radii and the CAM&apos;s line in the notes change, except where the library describes another cutter: that tool&apos;s TLO, length, wear and break mark end (the history keeps the TLO) and it is measured before it cuts. Pockets and your notes stay as they are.</source>
        <translation>只有描述、半径和备注中的 CAM 行会改变；但库描述的是另一把刀具时，该刀具的 TLO、长度、磨损和断刀标记作废（历史保留该 TLO），切削前需先测量。刀位和您的备注保持不变。</translation>
    </message>
</context>
<context>
    <name>Toffee::JobCheckDialog</name>
    <message>
        <source>Z &amp;floor:</source>
        <translation>Z 下限(&amp;F)：</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Check &amp;Again</source>
        <translation>重新检查(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Prepare…</source>
        <translation>准备(&amp;P)…</translation>
    </message>
    <message>
        <source>Tools in order of use</source>
        <translation>按使用顺序排列的刀具</translation>
    </message>
    <message>
        <source>Findings</source>
        <translation>问题</translation>
    </message>
    <message>
        <source>Check Job</source>
        <translation>检查作业</translation>
    </message>
    <message>
        <source>Controller</source>
        <translation>控制器</translation>
    </message>
    <message>
        <source>Lowest work Z a feed move may reach</source>
        <translation>进给移动可到达的最低工件 Z</translation>
    </message>
    <message>
        <source>The tools the Carvera&apos;s rack holds</source>
        <translation>Carvera 刀库中的刀具</translation>
    </message>
    <message>
        <source>The tools the rack holds: 1-6 on a Carvera C1, none on a machine without one, or a list such as 1-4,8. Every other tool is a manual change.</source>
        <translation>刀库中的刀具：Carvera C1 为 1-6，没有刀库的机床为 none，或写成列表，例如 1-4,8。其他刀具都需要手动换刀。</translation>
    </message>
    <message>
        <source>How far the check is</source>
        <translation>检查进度</translation>
    </message>
    <message>
        <source>The program around the finding</source>
        <translation>问题所在处的程序</translation>
    </message>
    <message>
        <source>Double-click a finding to see the program around its line.</source>
        <translation>双击某个问题，查看其所在行附近的程序。</translation>
    </message>
    <message>
        <source>Controller:</source>
        <translation>控制器：</translation>
    </message>
    <message>
        <source>&amp;Tools, in order of use</source>
        <translation>刀具（按使用顺序）(&amp;T)</translation>
    </message>
    <message>
        <source>F&amp;indings, by line</source>
        <translation>问题（按行）(&amp;I)</translation>
    </message>
    <message>
        <source>Program: %1</source>
        <translation>程序：%1</translation>
    </message>
    <message>
        <source>Checking…</source>
        <translation>正在检查…</translation>
    </message>
    <message>
        <source>The program could not be checked: %1</source>
        <translation>无法检查该程序：%1</translation>
    </message>
    <message>
        <source>%1: %2 lines as %3; tools: %4, cutting %5, rapids %6 mm.</source>
        <translation>%1：%2 行，按 %3 解读；刀具：%4，切削 %5，快速移动 %6 mm。</translation>
    </message>
    <message>
        <source>Cancelled after %1 lines: what was found so far.</source>
        <translation>在 %1 行后取消：以下为目前的结果。</translation>
    </message>
    <message>
        <source>The check found errors: fix them before preparing the program.</source>
        <translation>检查发现了错误：请先修正，再准备程序。</translation>
    </message>
    <message>
        <source>1-6, or none</source>
        <translation>1-6 或 none</translation>
    </message>
    <message>
        <source>&amp;Rack holds:</source>
        <translation>刀库包含(&amp;R)：</translation>
    </message>
    <message>
        <source>Only the first %1 tools are listed; the other %2 are counted, their findings summed up one for each kind.</source>
        <translation>仅列出前 %1 把刀具；其余 %2 把只计数，其问题按类别各汇总为一条。</translation>
    </message>
</context>
<context>
    <name>Toffee::JobChecker</name>
    <message>
        <source>A feed move before any tool change: the program does not say which tool is in the spindle.</source>
        <translation>在任何换刀之前就有进给移动：程序没有说明主轴上是哪把刀具。</translation>
    </message>
    <message>
        <source>T%1 feeds to work Z %2, below the floor of %3.</source>
        <translation>T%1 进给到工件 Z %2，低于下限 %3。</translation>
    </message>
    <message>
        <source>A feed move to work Z %1, below the floor of %2.</source>
        <translation>进给移动到工件 Z %1，低于下限 %2。</translation>
    </message>
    <message>
        <source>T%1 cuts with no length compensation: no G43 since it was loaded.</source>
        <translation>T%1 切削时没有刀具长度补偿：装刀后没有 G43。</translation>
    </message>
    <message>
        <source>T%1 cuts with %2%3 still in force from the tool before: no G43 %2%1 since its change.</source>
        <translation>T%1 切削时仍沿用上一把刀具的 %2%3：换刀后没有 G43 %2%1。</translation>
    </message>
    <message>
        <source>T%1 cuts with the length offset %2%3, which is another tool&apos;s.</source>
        <translation>T%1 切削时使用的长度补偿 %2%3 属于另一把刀具。</translation>
    </message>
    <message>
        <source>The program sets T%1&apos;s TLO to %2 itself; the table holds %3 for it.</source>
        <translation>程序自行将 T%1 的 TLO 设为 %2；刀具表中为 %3。</translation>
    </message>
    <message>
        <source>G20: the Carvera refuses inch programs (ALARM: Imperial Units are unsupported). Post the program in millimetres.</source>
        <translation>G20：Carvera 拒绝英制程序（ALARM: Imperial Units are unsupported）。请以毫米为单位后处理该程序。</translation>
    </message>
    <message>
        <source>The program is in inches (G20) but the tool table is in millimetres.</source>
        <translation>程序使用英寸（G20），但刀具表使用毫米。</translation>
    </message>
    <message>
        <source>The program is in millimetres (G21) but the tool table is in inches.</source>
        <translation>程序使用毫米（G21），但刀具表使用英寸。</translation>
    </message>
    <message>
        <source>More lines the controller would refuse, from this one on: %1 in all.</source>
        <translation>从此行起还有控制器会拒绝的行：共 %1 行。</translation>
    </message>
    <message>
        <source>The machine&apos;s rack does not hold T%1: it is a manual change, and the machine waits for the operator.</source>
        <translation>机床刀库中没有 T%1：需要手动换刀，机床会等待操作员。</translation>
    </message>
    <message>
        <source>T%1 is not in the tool table: nothing is known of its length.</source>
        <translation>T%1 不在刀具表中：其长度未知。</translation>
    </message>
    <message>
        <source>T%1 failed its last break test and has not been measured since: check the tool and probe it.</source>
        <translation>T%1 未通过上次断刀检测，此后也未测量：请检查刀具并对刀。</translation>
    </message>
    <message>
        <source>T%1 has no measured TLO.</source>
        <translation>T%1 没有测得的 TLO。</translation>
    </message>
    <message>
        <source>T%1 has no length in the table: G43 would apply 0.</source>
        <translation>T%1 在刀具表中没有长度：G43 将使用 0。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO is dated %2, in the future: a clock was wrong, and when it was measured is not known.</source>
        <translation>T%1 的 TLO 日期为 %2，在未来：某个时钟有误，无法知道它何时测量。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was measured %2, before the stale limit (%3 d).</source>
        <translation>T%1 的 TLO 测量于 %2，已超过过期期限（%3 天）。</translation>
    </message>
    <message>
        <source>The history has a newer measurement of T%1 (%2, %3) than the table&apos;s: the table was not saved after it.</source>
        <translation>历史中有比刀具表更新的 T%1 测量记录（%2，%3）：此后刀具表未保存。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was set by hand, not measured on the tool setter: probe it before the job.</source>
        <translation>T%1 的 TLO 是手动设置的，并非在对刀仪上测得：请在作业前对刀。</translation>
    </message>
    <message>
        <source>%1 more tools the table lacks</source>
        <translation>另有 %1 把刀具不在刀具表中</translation>
    </message>
    <message>
        <source>%1 more tools the machine&apos;s rack does not hold (manual changes)</source>
        <translation>另有 %1 把刀具不在机床刀库中（手动换刀）</translation>
    </message>
    <message>
        <source>%1 more tools with no TLO measured on the tool setter</source>
        <translation>另有 %1 把刀具没有在对刀仪上测得的 TLO</translation>
    </message>
    <message>
        <source>%1 more tools whose TLO is older than the stale limit (%2 d) or dated in the future</source>
        <translation>另有 %1 把刀具的 TLO 已超过过期期限（%2 天）或日期在未来</translation>
    </message>
    <message>
        <source>%1 more tools that failed their last break test</source>
        <translation>另有 %1 把刀具未通过上次断刀检测</translation>
    </message>
    <message>
        <source>%1 more tools feed below the floor of %2</source>
        <translation>另有 %1 把刀具进给到下限 %2 以下</translation>
    </message>
    <message>
        <source>%1 more tools cut with no length compensation</source>
        <translation>另有 %1 把刀具切削时没有刀具长度补偿</translation>
    </message>
    <message>
        <source>%1 more tools cut with another tool&apos;s length offset</source>
        <translation>另有 %1 把刀具切削时使用另一把刀具的长度补偿</translation>
    </message>
    <message>
        <source>%1 more tools have their TLO set by the program to another value than the table&apos;s</source>
        <translation>另有 %1 把刀具的 TLO 被程序设为与刀具表不同的值</translation>
    </message>
    <message>
        <source>%1, beyond the first %2 tools the program loads; the first of them is T%3. Counted, not listed, and judged by the table alone: the history library is read for the listed tools only.</source>
        <translation>%1，超出程序装入的前 %2 把刀具；其中第一把是 T%3。只计数、不列出，且仅依据刀具表判断：历史库只为列出的刀具读取。</translation>
    </message>
    <message>
        <source>%1, beyond the first %2 tools the program loads; the first of them is T%3. Counted, not listed.</source>
        <translation>%1，超出程序装入的前 %2 把刀具；其中第一把是 T%3。只计数，不列出。</translation>
    </message>
    <message>
        <source>The controller&apos;s own table has no T%1: G43 H%1 is refused. Renumber the tool, or apply its TLO with G43.1.</source>
        <translation>控制器自身的刀具表中没有 T%1：G43 H%1 会被拒绝。请为该刀具重新编号，或用 G43.1 应用其 TLO。</translation>
    </message>
    <message>
        <source>The controller&apos;s own table holds %1 for T%2, the table file %3: G43 H%2 would apply the controller&apos;s. Push the offsets (Machine ▸ Push Offsets…, toffee-cli push-offsets) or probe T%2 before the job.</source>
        <translation>控制器自身的刀具表中 T%2 为 %1，而刀具表文件中为 %3：G43 H%2 将应用控制器中的值。请在作业前推送补偿（机床 ▸ 向控制器推送补偿…，toffee-cli push-offsets），或对 T%2 对刀。</translation>
    </message>
    <message>
        <source>%1 more tools whose TLO in the controller&apos;s own table is not the file&apos;s</source>
        <translation>另有 %1 把刀具在控制器自身刀具表中的 TLO 与文件中的不一致</translation>
    </message>
    <message>
        <source>T%1 would pass its life limit of %2 min in this program: its cutter has cut %3 since it went in, and the program cuts %4 more. Put in a new cutter (Edit ▸ New Cutter…, toffee-cli new-cutter %1) or raise the limit.</source>
        <translation>T%1 在此程序中将超过其 %2 分钟的寿命上限：该刀具装入后已切削 %3，此程序还要切削 %4。请换上新刀具（编辑 ▸ 新刀具…，toffee-cli new-cutter %1）或提高上限。</translation>
    </message>
    <message>
        <source>T%1 would pass its life limit of %2 uses: its cutter has cut in %3 programs since it went in, and this is one more. Put in a new cutter (Edit ▸ New Cutter…, toffee-cli new-cutter %1) or raise the limit.</source>
        <translation>T%1 将超过其 %2 次的寿命上限：该刀具装入后已在 %3 个程序中切削，这是又一次。请换上新刀具（编辑 ▸ 新刀具…，toffee-cli new-cutter %1）或提高上限。</translation>
    </message>
    <message>
        <source>The history says T%1 got a new cutter %2, after the table&apos;s TLO was measured: that TLO is the old cutter&apos;s. Probe T%1 before the job.</source>
        <translation>历史记录显示 T%1 在 %2 换了新刀具，晚于表中 TLO 的测量时间：该 TLO 属于旧刀具。作业前请测量 T%1。</translation>
    </message>
    <message>
        <source>T%1 is past its life limit of %2 min already: its cutter has cut %3 since it went in, and the program cuts %4 more. Put in a new cutter (Edit ▸ New Cutter…, toffee-cli new-cutter %1) or raise the limit.</source>
        <translation>T%1 已超过其 %2 分钟的寿命上限：该刀具装入后已切削 %3，此程序还要切削 %4。请换上新刀具（编辑 ▸ 新刀具…，toffee-cli new-cutter %1）或提高上限。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was read from the controller&apos;s table, not measured on the tool setter: probe it before the job.</source>
        <translation>T%1 的 TLO 是从控制器的刀具表读取的，并未在对刀仪上测量：请在加工前测量。</translation>
    </message>
    <message>
        <source>T%1&apos;s edges differed by %2 when it was last measured, more than its limit %3: runout or a chipped edge. Look at the cutter and how it sits in its holder before it cuts.</source>
        <translation>T%1 上次测量时各刃相差 %2，超过其上限 %3：跳动或崩刃。切削前请检查刀具及其在刀柄中的安装。</translation>
    </message>
</context>
<context>
    <name>Toffee::JobFindingsModel</name>
    <message>
        <source>Error</source>
        <translation>错误</translation>
    </message>
    <message>
        <source>Warning</source>
        <translation>警告</translation>
    </message>
    <message>
        <source>%1 (%2 times: lines %3)</source>
        <translation>%1（%2 次：第 %3 行）</translation>
    </message>
    <message>
        <source>Severity</source>
        <translation>严重程度</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>行</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>刀具</translation>
    </message>
    <message>
        <source>Finding</source>
        <translation>问题</translation>
    </message>
    <message>
        <source>%1 tools</source>
        <translation>%1 把刀具</translation>
    </message>
</context>
<context>
    <name>Toffee::JobPrepareDialog</name>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>&amp;Save Prepared Program…</source>
        <translation>保存准备好的程序(&amp;S)…</translation>
    </message>
    <message>
        <source>Prepare %1 for %2</source>
        <translation>为 %2 准备 %1</translation>
    </message>
    <message>
        <source>After a manual change, set the tool&apos;s stored TLO instead of probing, when it is within the stale limit (%1 d)</source>
        <translation>手动换刀后，如果刀具的已存 TLO 未超过过期期限（%1 天），则设置该 TLO 而不对刀</translation>
    </message>
    <message>
        <source>Break-test each tool after its last cut, with the tolerance</source>
        <translation>在每把刀具最后一次切削后进行断刀检测，公差为</translation>
    </message>
    <message>
        <source>Break-test tolerance</source>
        <translation>断刀检测公差</translation>
    </message>
    <message>
        <source>%1: the missing G43 after each tool change is inserted, and nothing else.</source>
        <translation>%1：只在每次换刀后插入缺少的 G43，不做其他更改。</translation>
    </message>
    <message>
        <source>The original and the prepared program, side by side</source>
        <translation>原程序与准备好的程序并排对照</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>行</translation>
    </message>
    <message>
        <source>Original</source>
        <translation>原程序</translation>
    </message>
    <message>
        <source>Prepared</source>
        <translation>准备后</translation>
    </message>
    <message>
        <source>Preparing the preview…</source>
        <translation>正在准备预览…</translation>
    </message>
    <message>
        <source>Writing %1…</source>
        <translation>正在写入 %1…</translation>
    </message>
    <message>
        <source>Cancelled: nothing was written.</source>
        <translation>已取消：未写入任何内容。</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>未保存：%1</translation>
    </message>
    <message>
        <source>The program cannot be prepared: %1</source>
        <translation>无法准备该程序：%1</translation>
    </message>
    <message>
        <source>Written to %1.</source>
        <translation>已写入 %1。</translation>
    </message>
    <message>
        <source>Nothing to change: the program already does what these options ask.</source>
        <translation>无需更改：程序已符合这些选项的要求。</translation>
    </message>
    <message>
        <source>Lines inserted: %1, changed: %2. Cutting moves checked against the original: %3; each reaches the same work position with its tool&apos;s own offset.</source>
        <translation>插入 %1 行，修改 %2 行。已对照原程序检查的切削移动：%3 个；每个都以其刀具自己的补偿到达相同的工件位置。</translation>
    </message>
    <message>
        <source>The preview shows the first %1 changes; the other %2 are not shown.</source>
        <translation>预览显示前 %1 处更改；其余 %2 处未显示。</translation>
    </message>
    <message>
        <source>Save Prepared Program</source>
        <translation>保存准备好的程序</translation>
    </message>
    <message>
        <source>G-code programs (*.nc *.gcode *.ngc *.tap *.cnc);;All files (*)</source>
        <translation>G 代码程序 (*.nc *.gcode *.ngc *.tap *.cnc);;所有文件 (*)</translation>
    </message>
</context>
<context>
    <name>Toffee::JobPreparer</name>
    <message>
        <source>%1 has no stored-offset or break-test commands: --use-stored-tlo and --break-test are for the Carvera. For %1, prepare inserts only the missing G43.</source>
        <translation>%1 没有使用已存补偿或断刀检测的命令：--use-stored-tlo 和 --break-test 用于 Carvera。对于 %1，准备只会插入缺少的 G43。</translation>
    </message>
    <message>
        <source>Preparing a program is for the Carvera and the controllers with G43; Automation1 compensates with G143 / G144, which Toffee does not insert.</source>
        <translation>准备程序适用于 Carvera 和使用 G43 的控制器；Automation1 用 G143 / G144 进行补偿，而 Toffee 不会插入它们。</translation>
    </message>
    <message>
        <source>Say what to prepare: --use-stored-tlo, --break-test, or both.</source>
        <translation>请指定要准备的内容：--use-stored-tlo、--break-test 或两者。</translation>
    </message>
    <message>
        <source>The break-test tolerance must be from %1 mm (the Carvera halts below it) to %2 mm (a looser test would miss a broken tool).</source>
        <translation>断刀检测公差必须在 %1 mm（低于此值 Carvera 会停机）到 %2 mm（更宽松的检测会漏掉断刀）之间。</translation>
    </message>
    <message>
        <source>%1 Toffee prepares only a program the controller runs: check the job first.</source>
        <translation>%1 Toffee 只准备控制器能运行的程序：请先检查作业。</translation>
    </message>
    <message>
        <source>the line Toffee would insert here, &quot;%1&quot;, is refused: %2 Nothing was written.</source>
        <translation>Toffee 要在此处插入的行“%1”被拒绝：%2 未写入任何内容。</translation>
    </message>
    <message>
        <source>the line Toffee would insert here, &quot;%1&quot;, would move the machine. Nothing was written.</source>
        <translation>Toffee 要在此处插入的行“%1”会移动机床。未写入任何内容。</translation>
    </message>
    <message>
        <source>the prepared program could not be written.</source>
        <translation>无法写入准备好的程序。</translation>
    </message>
    <message>
        <source>the prepared line &quot;%1&quot; is refused: %2 Nothing was written.</source>
        <translation>准备后的行“%1”被拒绝：%2 未写入任何内容。</translation>
    </message>
    <message>
        <source>The program cuts before any tool change (original line %1): there is no tool to break-test.</source>
        <translation>程序在任何换刀之前就切削（原程序第 %1 行）：没有可进行断刀检测的刀具。</translation>
    </message>
    <message>
        <source>T%1 is in the rack: the Carvera measures a rack tool at every change.</source>
        <translation>T%1 在刀库中：Carvera 每次换刀都会测量刀库中的刀具。</translation>
    </message>
    <message>
        <source>the prepared program would put the machine elsewhere than the original with the table&apos;s offsets. Nothing was written.</source>
        <translation>使用刀具表中的补偿时，准备好的程序会使机床到达与原程序不同的位置。未写入任何内容。</translation>
    </message>
    <message>
        <source>the prepared program would cut at another work position than the original. Nothing was written.</source>
        <translation>准备好的程序会在与原程序不同的工件位置切削。未写入任何内容。</translation>
    </message>
    <message>
        <source>the prepared program would cut without T%1&apos;s length offset. Nothing was written.</source>
        <translation>准备好的程序会在没有 T%1 长度补偿的情况下切削。未写入任何内容。</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO does not say which reference it was measured against: check that it still holds.</source>
        <translation>T%1 的已存 TLO 未记录是相对于哪个基准测得的：请确认它仍然有效。</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO was measured against reference MCS Z %2 and T%3&apos;s against %4: the machine has one reference, so at most one is right. Probe one of them again, or prepare without stored TLOs. Nothing was written.</source>
        <translation>T%1 的已存 TLO 是相对于基准 MCS Z %2 测得的，而 T%3 的是相对于 %4：机床只有一个基准，因此最多只有一个正确。请对其中一把刀具重新对刀，或不使用已存 TLO 进行准备。未写入任何内容。</translation>
    </message>
    <message>
        <source>%1 more notes like these, one for each further tool (the first of them T%2): counted, not listed.</source>
        <translation>另有 %1 条类似说明，每把后续刀具一条（其中第一把为 T%2）：只计数，不列出。</translation>
    </message>
    <message>
        <source>The stored TLOs hold only while the machine&apos;s reference MCS Z is %1 (its calibration): check it before running the program.</source>
        <translation>已存 TLO 仅在机床的基准 MCS Z 为 %1（其校准值）时有效：运行程序前请检查。</translation>
    </message>
</context>
<context>
    <name>Toffee::JobReport</name>
    <message>
        <source>no findings</source>
        <translation>未发现问题</translation>
    </message>
    <message>
        <source>1 error</source>
        <translation>1 个错误</translation>
    </message>
    <message>
        <source>%1 errors</source>
        <translation>%1 个错误</translation>
    </message>
    <message>
        <source>1 warning</source>
        <translation>1 个警告</translation>
    </message>
    <message>
        <source>%1 warnings</source>
        <translation>%1 个警告</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1，%2</translation>
    </message>
</context>
<context>
    <name>Toffee::JobToolsModel</name>
    <message>
        <source>not in the table</source>
        <translation>不在刀具表中</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>未测量</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>刀具</translation>
    </message>
    <message>
        <source>Loaded at line</source>
        <translation>换刀行</translation>
    </message>
    <message>
        <source>TLO (mm)</source>
        <translation>TLO（mm）</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>测量时间</translation>
    </message>
    <message>
        <source>Cutting time</source>
        <translation>切削时间</translation>
    </message>
    <message>
        <source>Feed path (mm)</source>
        <translation>进给路径（mm）</translation>
    </message>
    <message>
        <source>Lowest cut Z (mm)</source>
        <translation>最低切削 Z（mm）</translation>
    </message>
    <message>
        <source>%1 (by hand)</source>
        <translation>%1（手动）</translation>
    </message>
    <message>
        <source>set %1</source>
        <translation>设置于 %1</translation>
    </message>
    <message>
        <source>%1 more</source>
        <translation>另有 %1 把</translation>
    </message>
    <message>
        <source>from line %1, %2 loads: counted, not listed</source>
        <translation>自第 %1 行起，换刀 %2 次：只计数，不列出</translation>
    </message>
    <message>
        <source>The program loads %1 distinct tools: the first %2 are listed, the other %3 only counted. Their findings are summed up, one for each kind.</source>
        <translation>程序装入 %1 把不同的刀具：列出前 %2 把，其余 %3 把只计数。它们的问题按类别各汇总为一条。</translation>
    </message>
</context>
<context>
    <name>Toffee::JsonScanner</name>
    <message>
        <source>this is not valid JSON: expected %1.</source>
        <translation>这不是有效的 JSON：应为 %1。</translation>
    </message>
    <message>
        <source>this is not valid JSON: a line break or control character inside a string; write it as \n.</source>
        <translation>这不是有效的 JSON：字符串中有换行或控制字符；请写成 \n。</translation>
    </message>
    <message>
        <source>this is not valid JSON: a lone UTF-16 surrogate in a \u escape.</source>
        <translation>这不是有效的 JSON：\u 转义中有单独的 UTF-16 代理项。</translation>
    </message>
    <message>
        <source>this is not valid JSON: unknown escape \%1 in a string.</source>
        <translation>这不是有效的 JSON：字符串中有未知转义 \%1。</translation>
    </message>
    <message>
        <source>this is not valid JSON: a string is never closed.</source>
        <translation>这不是有效的 JSON：有一个字符串没有结束。</translation>
    </message>
    <message>
        <source>the number %1 is too large.</source>
        <translation>数字 %1 太大。</translation>
    </message>
    <message>
        <source>this is not valid JSON: a \u escape needs four hex digits.</source>
        <translation>这不是有效的 JSON：\u 转义需要四个十六进制数字。</translation>
    </message>
    <message>
        <source>a string is not valid UTF-8 text.</source>
        <translation>字符串不是有效的 UTF-8 文本。</translation>
    </message>
    <message>
        <source>the text &quot;%1&quot; is longer than %2 KB; no field of a tool table holds that much.</source>
        <translation>文本“%1”超过 %2 KB；刀具表的任何字段都容纳不了这么多。</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; appears twice at the top level; Toffee will not guess which one is meant.</source>
        <translation>键“%1”在最外层出现了两次；Toffee 不会猜测指的是哪一个。</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; appears twice in one object; Toffee will not guess which one is meant.</source>
        <translation>键“%1”在同一个对象中出现了两次；Toffee 不会猜测指的是哪一个。</translation>
    </message>
    <message>
        <source>the key &quot;%1&quot; appears twice in &quot;%2&quot;; Toffee will not guess which one is meant.</source>
        <translation>键“%1”在“%2”中出现了两次；Toffee 不会猜测指的是哪一个。</translation>
    </message>
    <message>
        <source>this is not JSON Toffee reads: it is nested too deeply (more than %1 levels).</source>
        <translation>这不是 Toffee 可读取的 JSON：嵌套过深（超过 %1 层）。</translation>
    </message>
</context>
<context>
    <name>Toffee::Library</name>
    <message>
        <source>Adding the machine %1</source>
        <translation>添加机器 %1</translation>
    </message>
    <message>
        <source>Reading the machines</source>
        <translation>读取机器</translation>
    </message>
    <message>
        <source>Recording T%1&apos;s %2</source>
        <translation>记录 T%1 的 %2</translation>
    </message>
    <message>
        <source>Recording T%1&apos;s use</source>
        <translation>记录 T%1 的使用</translation>
    </message>
    <message>
        <source>Reading the history</source>
        <translation>读取历史</translation>
    </message>
    <message>
        <source>Reading the tools&apos; use</source>
        <translation>读取刀具使用</translation>
    </message>
    <message>
        <source>%1 is a folder, not a library file. Choose a file in it, such as %2.</source>
        <translation>%1 是文件夹，不是库文件。请选择其中的文件，例如 %2。</translation>
    </message>
    <message>
        <source>%1 is not a regular file: a library is an SQLite file.</source>
        <translation>%1 不是普通文件：库是一个 SQLite 文件。</translation>
    </message>
    <message>
        <source>%1 is not a Toffee library: it is not an SQLite database. Choose another file, or move this one away.</source>
        <translation>%1 不是 Toffee 库：它不是 SQLite 数据库。请选择另一个文件，或将此文件移走。</translation>
    </message>
    <message>
        <source>The folder of %1 cannot be created.</source>
        <translation>无法创建 %1 所在的文件夹。</translation>
    </message>
    <message>
        <source>Qt&apos;s SQLite driver is missing: install libqt6sql6-sqlite.</source>
        <translation>缺少 Qt 的 SQLite 驱动：请安装 libqt6sql6-sqlite。</translation>
    </message>
    <message>
        <source>%1 cannot be opened: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>%1: %2 failed: %3</source>
        <translation>%1：%2 失败：%3</translation>
    </message>
    <message>
        <source>%1 is damaged or is not a library: %2. Move it away (Toffee then starts a new one), or choose another file.</source>
        <translation>%1 已损坏或不是库：%2。请将其移走（Toffee 会新建一个），或选择另一个文件。</translation>
    </message>
    <message>
        <source>%1 was written by a newer Toffee (library version %2; this Toffee knows up to %3). It was not changed: use a newer Toffee with it, or choose another library.</source>
        <translation>%1 由较新的 Toffee 写入（库版本 %2；此 Toffee 最高支持 %3）。该库未被更改：请使用较新的 Toffee，或选择另一个库。</translation>
    </message>
    <message>
        <source>Reading the library</source>
        <translation>读取库</translation>
    </message>
    <message>
        <source>Reading the library&apos;s version</source>
        <translation>读取库的版本</translation>
    </message>
    <message>
        <source>Creating the library</source>
        <translation>创建库</translation>
    </message>
    <message>
        <source>Bringing the library to version %1</source>
        <translation>将库升级到版本 %1</translation>
    </message>
    <message>
        <source>Bringing the library up to date</source>
        <translation>更新库</translation>
    </message>
    <message>
        <source>your login name</source>
        <translation>您的登录名</translation>
    </message>
    <message>
        <source>The server refused %1&apos;s password. Put the right one in the PostgreSQL password file (~/.pgpass, or the file PGPASSFILE names): Toffee never stores one.</source>
        <translation>服务器拒绝了 %1 的密码。请将正确的密码写入 PostgreSQL 密码文件（~/.pgpass，或 PGPASSFILE 指定的文件）：Toffee 从不保存密码。</translation>
    </message>
    <message>
        <source>The server has no database &quot;%1&quot;. Check the name in the URL, or have it created (createdb %1; docs/LIBRARY.md).</source>
        <translation>服务器上没有数据库“%1”。请检查 URL 中的名称，或请人创建该数据库（createdb %1；docs/LIBRARY.md）。</translation>
    </message>
    <message>
        <source>The server has no user &quot;%1&quot;. Check the user in the URL, or have the role created (docs/LIBRARY.md).</source>
        <translation>服务器上没有用户“%1”。请检查 URL 中的用户，或请人创建该角色（docs/LIBRARY.md）。</translation>
    </message>
    <message>
        <source>The server&apos;s name &quot;%1&quot; is not known here. Check the host in the URL.</source>
        <translation>此处无法识别服务器名“%1”。请检查 URL 中的主机。</translation>
    </message>
    <message>
        <source>The connection&apos;s encryption failed. Check sslmode in the URL against the server&apos;s settings.</source>
        <translation>连接加密失败。请对照服务器的设置检查 URL 中的 sslmode。</translation>
    </message>
    <message>
        <source>The server cannot be reached. Check that it is running and that the host and port in the URL are right.</source>
        <translation>无法连接服务器。请检查它是否正在运行，以及 URL 中的主机和端口是否正确。</translation>
    </message>
    <message>
        <source>The library (%1) cannot be opened. %2 (The server said: %3)</source>
        <translation>无法打开刀具库（%1）。%2（服务器返回：%3）</translation>
    </message>
    <message>
        <source>Qt&apos;s PostgreSQL driver is missing: install libqt6sql6-psql to use %1.</source>
        <translation>缺少 Qt 的 PostgreSQL 驱动：请安装 libqt6sql6-psql 以使用 %1。</translation>
    </message>
    <message>
        <source>Reading the server&apos;s version</source>
        <translation>读取服务器版本</translation>
    </message>
    <message>
        <source>The library (%1) is on PostgreSQL %2, which this Toffee does not support: it needs %3 or newer. Upgrade the server, or use another one.</source>
        <translation>刀具库（%1）位于 PostgreSQL %2 上，此 Toffee 不支持该版本：需要 %3 或更新版本。请升级服务器，或使用其他服务器。</translation>
    </message>
    <message>
        <source>Reading your rights in the library</source>
        <translation>读取您在刀具库中的权限</translation>
    </message>
    <message>
        <source>%1 is a database, but not a Toffee library (it has tables of its own). Choose another one.</source>
        <translation>%1 是数据库，但不是 Toffee 库（它有自己的表）。请选择另一个。</translation>
    </message>
    <message>
        <source>The library (%1) is read-only for %2: this role may read the tools but not change them. Ask whoever runs the server for write rights (docs/LIBRARY.md).</source>
        <translation>刀具库（%1）对 %2 是只读的：此角色可以读取刀具，但不能更改。请向服务器的管理员申请写入权限（docs/LIBRARY.md）。</translation>
    </message>
    <message>
        <source>you</source>
        <translation>您</translation>
    </message>
    <message>
        <source>%1 is read-only: it cannot be written.</source>
        <translation>%1 是只读的：无法写入。</translation>
    </message>
    <message>
        <source>Announcing the change</source>
        <translation>通告更改</translation>
    </message>
    <message>
        <source>Reading the machine tables</source>
        <translation>读取机床刀具表</translation>
    </message>
    <message>
        <source>Reading %1&apos;s table</source>
        <translation>读取 %1 的刀具表</translation>
    </message>
    <message>
        <source>The library has no tool table for %1.</source>
        <translation>刀具库中没有 %1 的刀具表。</translation>
    </message>
    <message>
        <source>Reading T%1 of %2</source>
        <translation>读取 %2 的 T%1</translation>
    </message>
    <message>
        <source>Writing T%1 of %2</source>
        <translation>写入 %2 的 T%1</translation>
    </message>
    <message>
        <source>Adding %1&apos;s table</source>
        <translation>添加 %1 的刀具表</translation>
    </message>
    <message>
        <source>The library already has a tool table for %1: open it, or choose another name.</source>
        <translation>刀具库中已有 %1 的刀具表：请打开它，或选择其他名称。</translation>
    </message>
    <message>
        <source>T%1 of %2 kept changing while it was written.</source>
        <translation>写入期间，%2 的 T%1 一直在被更改。</translation>
    </message>
    <message>
        <source>Keeping a change for later</source>
        <translation>暂存一项更改以便稍后写入</translation>
    </message>
    <message>
        <source>Reading the changes kept for later</source>
        <translation>读取暂存的更改</translation>
    </message>
    <message>
        <source>Clearing a change written</source>
        <translation>清除已写入的更改</translation>
    </message>
    <message>
        <source>A tool&apos;s row does not hold one tool in its table&apos;s units.</source>
        <translation>某把刀具的行中并不是一把以其刀具表单位表示的刀具。</translation>
    </message>
    <message>
        <source>An outbox entry cannot be read; it is kept as it is.</source>
        <translation>无法读取发件箱中的一个条目；它将保持原样。</translation>
    </message>
    <message>
        <source>The library (%1) was busy: another station or program held what Toffee needed (%2) for more than %3 s, Toffee&apos;s limit.</source>
        <translation>库（%1）正忙：另一个工位或程序占用了 Toffee 所需的资源（%2），超过了 Toffee 的时限 %3 秒。</translation>
    </message>
    <message>
        <source>a table or column Toffee needs is missing (%1)</source>
        <translation>缺少 Toffee 需要的表或列（%1）</translation>
    </message>
    <message>
        <source>the database gave no reason</source>
        <translation>数据库未给出原因</translation>
    </message>
    <message>
        <source>Starting a write</source>
        <translation>开始写入</translation>
    </message>
    <message>
        <source>Setting how long to wait</source>
        <translation>设置等待时限</translation>
    </message>
    <message>
        <source>Writing</source>
        <translation>写入</translation>
    </message>
    <message>
        <source>%1 is damaged: %2. Toffee leaves it as it is and writes nothing into it: restore it from a backup (docs/LIBRARY.md), or choose another library.</source>
        <translation>%1 已损坏：%2。Toffee 保持原样，不写入任何内容：请从备份恢复（docs/LIBRARY.md），或选择其他库。</translation>
    </message>
    <message>
        <source>its table &quot;%1&quot; is missing</source>
        <translation>其表“%1”缺失</translation>
    </message>
    <message>
        <source>its table &quot;%1&quot; was altered: it has no column &quot;%2&quot;</source>
        <translation>其表“%1”已被修改：没有列“%2”</translation>
    </message>
    <message>
        <source>its version table (toffee_schema) is empty, so it cannot say which Toffee wrote it</source>
        <translation>其版本表（toffee_schema）为空，无法说明由哪个 Toffee 写入</translation>
    </message>
    <message>
        <source>its version table (toffee_schema) holds more than one version</source>
        <translation>其版本表（toffee_schema）包含多个版本</translation>
    </message>
    <message>
        <source>its schema version is &quot;%1&quot;, which is not a version any Toffee writes</source>
        <translation>其架构版本为“%1”，这不是任何 Toffee 会写入的版本</translation>
    </message>
    <message>
        <source>%1: %2&apos;s table says its units are %3, neither mm nor in; it was written by another program or by hand, and is not opened.</source>
        <translation>%1：%2 的表声明其单位为 %3，既不是 mm 也不是 in；它由其他程序或手工写入，因此不会打开。</translation>
    </message>
    <message>
        <source>%1: %2&apos;s table has rows Toffee cannot read, so it is not opened and nothing was written: %3. They were written by another program or by hand; put the table back from a backup, or have whoever changed them correct them (docs/LIBRARY.md).</source>
        <translation>%1：%2 的表中有 Toffee 无法读取的行，因此不会打开，也未写入任何内容：%3。这些行由其他程序或手工写入；请从备份恢复该表，或请修改者更正（docs/LIBRARY.md）。</translation>
    </message>
    <message>
        <source>%1: %2&apos;s table has units %3, neither mm nor in.</source>
        <translation>%1：%2 的表单位为 %3，既不是 mm 也不是 in。</translation>
    </message>
    <message>
        <source>%1: %2&apos;s %3. Nothing was written to it.</source>
        <translation>%1：%2 的%3。未写入任何内容。</translation>
    </message>
    <message>
        <source>and %1 more</source>
        <translation>以及另外 %1 个</translation>
    </message>
    <message>
        <source>Keeping %1&apos;s tool setter</source>
        <translation>保存 %1 的对刀仪</translation>
    </message>
    <message>
        <source>Reading %1&apos;s tool setter</source>
        <translation>读取 %1 的对刀仪</translation>
    </message>
    <message>
        <source>%1&apos;s tool setter in the library (&quot;%2&quot;) does not read: %3 Set it again (Machine ▸ Tool Setter…).</source>
        <translation>刀具库中 %1 的对刀仪（“%2”）无法读取：%3 请重新设置（机床 ▸ 对刀仪…）。</translation>
    </message>
    <message>
        <source>Nothing of this batch was recorded.</source>
        <translation>本批次中的任何内容都未记录。</translation>
    </message>
    <message>
        <source>%1 is a library of version %2, read-only here, and too old to be read as it is. Open it once where it can be written (Toffee brings it up to date), or copy it.</source>
        <translation>%1 是版本 %2 的库，此处为只读，且版本太旧，无法按原样读取。请在可写的地方打开一次（Toffee 会将其升级），或复制它。</translation>
    </message>
    <message>
        <source>Reading which machine %1 is</source>
        <translation>读取 %1 是哪台机器</translation>
    </message>
    <message>
        <source>Keeping which machine %1 is</source>
        <translation>保存 %1 是哪台机器</translation>
    </message>
    <message>
        <source>A setter&apos;s repeatability takes 2 to %1 touches, each a machine position, and a time.</source>
        <translation>对刀仪的重复精度需要 2 到 %1 次触碰（每次为一个机床位置）和一个时间。</translation>
    </message>
    <message>
        <source>Keeping %1&apos;s setter repeatability</source>
        <translation>保存 %1 的对刀仪重复精度</translation>
    </message>
    <message>
        <source>%1&apos;s setter repeatability in the library does not read; measure it again (toffee-cli measure-repeatability).</source>
        <translation>库中 %1 的对刀仪重复精度无法读取；请重新测量（toffee-cli measure-repeatability）。</translation>
    </message>
</context>
<context>
    <name>Toffee::LibraryLocation</name>
    <message>
        <source>%1 is not a valid PostgreSQL URL (%2). Write it as postgresql://user@host:port/dbname.</source>
        <translation>%1 不是有效的 PostgreSQL URL（%2）。请写成 postgresql://user@host:port/dbname。</translation>
    </message>
    <message>
        <source>%1 holds a password. Toffee never stores one: take it out of the URL and put it in the PostgreSQL password file (~/.pgpass, or the file PGPASSFILE names).</source>
        <translation>%1 中含有密码。Toffee 从不保存密码：请将其从 URL 中删除，并写入 PostgreSQL 密码文件（~/.pgpass，或 PGPASSFILE 指定的文件）。</translation>
    </message>
    <message>
        <source>%1 names no database: write it after the host, as in postgresql://toffee@server/tools.</source>
        <translation>%1 未指定数据库：请将其写在主机之后，例如 postgresql://toffee@server/tools。</translation>
    </message>
    <message>
        <source>%1: the database is named by one path part, as in postgresql://host/dbname.</source>
        <translation>%1：数据库名只能是一段路径，例如 postgresql://host/dbname。</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a connection setting Toffee passes on (it takes %3).</source>
        <translation>%1：“%2”不是 Toffee 会传递的连接设置（它接受 %3）。</translation>
    </message>
    <message>
        <source>%1: the port must be between 1 and 65535.</source>
        <translation>%1：端口必须在 1 到 65535 之间。</translation>
    </message>
    <message>
        <source>No library was given: name an SQLite file, such as sqlite:library.sqlite, or a PostgreSQL database, such as postgresql://toffee@server/tools.</source>
        <translation>未给出库：请指定一个 SQLite 文件，例如 sqlite:library.sqlite，或一个 PostgreSQL 数据库，例如 postgresql://toffee@server/tools。</translation>
    </message>
    <message>
        <source>%1: Toffee reads a library from an SQLite file (a path, or sqlite:PATH) or from PostgreSQL (postgresql://…), not from &quot;%2&quot;.</source>
        <translation>%1：Toffee 从 SQLite 文件（路径或 sqlite:路径）或 PostgreSQL（postgresql://…）读取库，而不是从“%2”。</translation>
    </message>
    <message>
        <source>database %1 on %2</source>
        <translation>%2 上的数据库 %1</translation>
    </message>
    <message>
        <source>the local server</source>
        <translation>本地服务器</translation>
    </message>
</context>
<context>
    <name>Toffee::LibraryStatusLabel</name>
    <message>
        <source>Library status</source>
        <translation>刀具库状态</translation>
    </message>
    <message>
        <source>Library offline — 1 change waiting</source>
        <translation>刀具库离线 — 1 项更改等待写入</translation>
    </message>
    <message>
        <source>Library offline — %1 changes waiting</source>
        <translation>刀具库离线 — %1 项更改等待写入</translation>
    </message>
    <message>
        <source>Library cannot be written — 1 change waiting</source>
        <translation>刀具库无法写入 — 1 项更改等待写入</translation>
    </message>
    <message>
        <source>Library cannot be written — %1 changes waiting</source>
        <translation>刀具库无法写入 — %1 项更改等待写入</translation>
    </message>
    <message>
        <source>Library: %1 (read-only)</source>
        <translation>刀具库：%1（只读）</translation>
    </message>
    <message>
        <source>Library: %1</source>
        <translation>刀具库：%1</translation>
    </message>
    <message>
        <source>Library back: nothing was waiting</source>
        <translation>刀具库已恢复：没有等待写入的更改</translation>
    </message>
    <message>
        <source>Library back: 1 change written</source>
        <translation>刀具库已恢复：已写入 1 项更改</translation>
    </message>
    <message>
        <source>Library back: %1 changes written</source>
        <translation>刀具库已恢复：已写入 %1 项更改</translation>
    </message>
    <message>
        <source>Library read-only — 1 change kept on this station</source>
        <translation>刀具库只读 — 1 项更改保存在本工作站</translation>
    </message>
    <message>
        <source>Library read-only — %1 changes kept on this station</source>
        <translation>刀具库只读 — %1 项更改保存在本工作站</translation>
    </message>
</context>
<context>
    <name>Toffee::LineReader</name>
    <message>
        <source>line %1 holds a NUL byte: this is not a text program (UTF-16, or not text at all?). Save it as plain text (UTF-8 or ASCII).</source>
        <translation>第 %1 行含有 NUL 字节：这不是文本程序（是 UTF-16，还是根本不是文本？）。请将其另存为纯文本（UTF-8 或 ASCII）。</translation>
    </message>
    <message>
        <source>line %1 is longer than %2 KB; no program line is.</source>
        <translation>第 %1 行超过 %2 KB；程序行不会这么长。</translation>
    </message>
</context>
<context>
    <name>Toffee::LinuxCncAccessDialog</name>
    <message>
        <source>LinuxCNC Access for %1</source>
        <translation>%1 的 LinuxCNC 访问</translation>
    </message>
    <message>
        <source>found by itself when LinuxCNC runs on this computer</source>
        <translation>LinuxCNC 在本机运行时自动查找</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s default (EMCTOO)</source>
        <translation>LinuxCNC 的默认值（EMCTOO）</translation>
    </message>
    <message>
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s INI</source>
        <translation>LinuxCNC 的 INI 文件</translation>
    </message>
    <message>
        <source>LinuxCNC configurations (*.ini);;All files (*)</source>
        <translation>LinuxCNC 配置 (*.ini);;所有文件 (*)</translation>
    </message>
    <message>
        <source>linuxcncrsh cannot read LinuxCNC&apos;s tool table, so Toffee reads the file its INI names ([EMCIO] TOOL_TABLE) for push, pull and the job check. Its enable password lets Toffee take control (linuxcncrsh --enablepw); it is kept on this computer and never shown or logged.</source>
        <translation>linuxcncrsh 无法读取 LinuxCNC 的刀具表，因此 Toffee 在推送、拉取和程序检查时读取其 INI 指定的文件（[EMCIO] TOOL_TABLE）。启用密码让 Toffee 取得控制权（linuxcncrsh --enablepw）；它只保存在本机，从不显示或记录。</translation>
    </message>
    <message>
        <source>&amp;INI file:</source>
        <translation>INI 文件(&amp;I)：</translation>
    </message>
    <message>
        <source>&amp;Enable password:</source>
        <translation>启用密码(&amp;E)：</translation>
    </message>
</context>
<context>
    <name>Toffee::LinuxCncController</name>
    <message>
        <source>The line &quot;%1&quot; is too long for linuxcncrsh; nothing was sent.</source>
        <translation>“%1”这一行对 linuxcncrsh 来说太长；未发送任何内容。</translation>
    </message>
    <message>
        <source>Stopped: LinuxCNC aborted &quot;%1&quot; where the machine stood. Nothing was measured or written; check where the spindle is before you go on.</source>
        <translation>已停止：LinuxCNC 在机床当时所在的位置中止了“%1”。未测量也未写入任何内容；继续之前请检查主轴的位置。</translation>
    </message>
    <message>
        <source>LinuxCNC refused &quot;%1&quot; and did not say why (get error: OK). Check LinuxCNC&apos;s own screen.</source>
        <translation>LinuxCNC 拒绝了“%1”，但未说明原因（get error: OK）。请查看 LinuxCNC 自己的界面。</translation>
    </message>
    <message>
        <source>LinuxCNC refused &quot;%1&quot;: %2</source>
        <translation>LinuxCNC 拒绝了“%1”：%2</translation>
    </message>
    <message>
        <source>linuxcncrsh answered &quot;get %1&quot; with something else (%2); is this LinuxCNC?</source>
        <translation>linuxcncrsh 对“get %1”的回答不符（%2）；这是 LinuxCNC 吗？</translation>
    </message>
    <message>
        <source>linuxcncrsh refused Toffee&apos;s hello (HELLO NAK): it was started with a connect password of its own (--connectpw), which Toffee does not know. Start it with the default (EMC), then connect again.</source>
        <translation>linuxcncrsh 拒绝了 Toffee 的 hello（HELLO NAK）：它启动时使用了自定义的连接密码（--connectpw），Toffee 不知道该密码。请用默认密码（EMC）启动它，然后重新连接。</translation>
    </message>
    <message>
        <source>LinuxCNC refused the enable password in this machine&apos;s settings (linuxcncrsh --enablepw). Set the right one, then connect again. Nothing was sent.</source>
        <translation>LinuxCNC 拒绝了本机床设置中的启用密码（linuxcncrsh --enablepw）。请设置正确的密码后重新连接。未发送任何内容。</translation>
    </message>
    <message>
        <source>This LinuxCNC&apos;s machine units are %1 ([TRAJ] LINEAR_UNITS); Toffee reads and writes millimetres only. Nothing was sent.</source>
        <translation>此 LinuxCNC 的机床单位是 %1（[TRAJ] LINEAR_UNITS）；Toffee 只读写毫米。未发送任何内容。</translation>
    </message>
    <message>
        <source>select a tool</source>
        <translation>选择刀具</translation>
    </message>
    <message>
        <source>LinuxCNC was told T%1 is in the spindle but says T%2.</source>
        <translation>已告知 LinuxCNC 主轴上是 T%1，但它报告的是 T%2。</translation>
    </message>
    <message>
        <source>T%1 may be asked for at LinuxCNC&apos;s own screen (its manual tool change)</source>
        <translation>LinuxCNC 自己的界面可能会要求装入 T%1（其手动换刀）</translation>
    </message>
    <message>
        <source>LinuxCNC changes to a tool, not to an empty spindle: use Select Tool with T0.</source>
        <translation>LinuxCNC 只能换到某把刀具，不能换成空主轴：请使用“选择刀具”并选 T0。</translation>
    </message>
    <message>
        <source>change tools</source>
        <translation>换刀</translation>
    </message>
    <message>
        <source>LinuxCNC ended the change to T%1 with T%2 in the spindle: nothing was measured.</source>
        <translation>LinuxCNC 结束了换到 T%1 的换刀，但主轴上是 T%2：未测量任何数据。</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s change was aborted (set abort): check what is in the spindle, then select it and restore or probe its TLO before cutting.</source>
        <translation>LinuxCNC 的换刀已中止（set abort）：请检查主轴上装的是什么，然后选择它，并在切削前恢复或测量其 TLO。</translation>
    </message>
    <message>
        <source>Toffee cannot %1 now: </source>
        <translation>Toffee 现在无法%1：</translation>
    </message>
    <message>
        <source>Nothing was sent.</source>
        <translation>未发送任何内容。</translation>
    </message>
    <message>
        <source>LinuxCNC is in estop. Release it at the machine (in AXIS: F1), then try again; Toffee never releases an estop itself.</source>
        <translation>LinuxCNC 处于急停（estop）状态。请在机床上解除急停（AXIS 中按 F1）后重试；Toffee 从不自行解除急停。</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s machine is off. Switch it on (in AXIS: F2), then try again.</source>
        <translation>LinuxCNC 的机床处于关闭状态。请将其开启（AXIS 中按 F2）后重试。</translation>
    </message>
    <message>
        <source>LinuxCNC is not homed. Home every axis (in AXIS: Ctrl-Home), then try again.</source>
        <translation>LinuxCNC 尚未回零。请让所有轴回零（AXIS 中按 Ctrl-Home）后重试。</translation>
    </message>
    <message>
        <source>LinuxCNC is running a program or a line (%1). Wait until it is idle, then try again.</source>
        <translation>LinuxCNC 正在运行程序或单行代码（%1）。请等它空闲后重试。</translation>
    </message>
    <message>
        <source>LinuxCNC is in %1 mode; Toffee works through MDI and does not switch modes itself (a switch aborts whatever runs). Switch it to MDI (in AXIS: F5), then try again.</source>
        <translation>LinuxCNC 处于 %1 模式；Toffee 通过 MDI 工作，不会自行切换模式（切换会中止正在运行的任何内容）。请切换到 MDI（AXIS 中按 F5）后重试。</translation>
    </message>
    <message>
        <source>Another program took control of LinuxCNC (linuxcncrsh&apos;s enable) since Toffee connected. Make sure nobody else is driving it, then connect again.</source>
        <translation>自 Toffee 连接以来，另一个程序取得了 LinuxCNC 的控制权（linuxcncrsh 的 enable）。请确认没有其他人在操作它，然后重新连接。</translation>
    </message>
    <message>
        <source>LinuxCNC is in inches (G20), where G10 and G38.2 take inches. Toffee works in millimetres: send G21, then try again.</source>
        <translation>LinuxCNC 处于英寸模式（G20），此时 G10 和 G38.2 以英寸计。Toffee 以毫米工作：请发送 G21 后重试。</translation>
    </message>
    <message>
        <source>LinuxCNC did not print what Toffee asked of it (%1); it said &quot;%2&quot;. Nothing was recorded.</source>
        <translation>LinuxCNC 没有输出 Toffee 请求的内容（%1）；它返回的是“%2”。未记录任何内容。</translation>
    </message>
    <message>
        <source>Cannot read LinuxCNC&apos;s INI %1: %2</source>
        <translation>无法读取 LinuxCNC 的 INI 文件 %1：%2</translation>
    </message>
    <message>
        <source>linuxcncrsh cannot read LinuxCNC&apos;s tool table, so Toffee reads its file: give the INI LinuxCNC runs (toffee-cli --ini FILE) on the computer LinuxCNC runs on.</source>
        <translation>linuxcncrsh 无法读取 LinuxCNC 的刀具表，因此 Toffee 直接读取其文件：请在运行 LinuxCNC 的计算机上指定 LinuxCNC 所用的 INI 文件（toffee-cli --ini FILE）。</translation>
    </message>
    <message>
        <source>Cannot read LinuxCNC&apos;s tool table %1: %2</source>
        <translation>无法读取 LinuxCNC 的刀具表 %1：%2</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s tool table %1 could not be read: %2</source>
        <translation>LinuxCNC 的刀具表 %1 读取失败：%2</translation>
    </message>
    <message>
        <source>LinuxCNC says no tool is in the spindle (T0), so there is nothing to %1. Say which tool is in (Select Tool, M61 Q&lt;n&gt;) first.</source>
        <translation>LinuxCNC 报告主轴上没有刀具（T0），因此无法%1。请先指明装的是哪把刀具（选择刀具，M61 Q&lt;n&gt;）。</translation>
    </message>
    <message>
        <source>Toffee does not know where this machine&apos;s tool setter is. Set it first (Machine ▸ Tool Setter…, or toffee-cli --setter X,Y,ZMIN in machine coordinates).</source>
        <translation>Toffee 不知道这台机床的对刀仪在哪里。请先设置（机床 ▸ 对刀仪…，或用 toffee-cli --setter X,Y,ZMIN 以机床坐标指定）。</translation>
    </message>
    <message>
        <source>probe</source>
        <translation>探测</translation>
    </message>
    <message>
        <source>measure</source>
        <translation>测量</translation>
    </message>
    <message>
        <source>break-test</source>
        <translation>进行断刀检测</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO</source>
        <translation>T%1 的 TLO</translation>
    </message>
    <message>
        <source>Nothing was written to LinuxCNC or recorded.</source>
        <translation>未写入 LinuxCNC，也未记录任何内容。</translation>
    </message>
    <message>
        <source>the offset in force reads %1 mm</source>
        <translation>当前生效的补偿读数为 %1 mm</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>无</translation>
    </message>
    <message>
        <source>%1 holds %2 for T%3</source>
        <translation>%1 中 T%3 的值为 %2</translation>
    </message>
    <message>
        <source>LinuxCNC was given T%1&apos;s TLO %2 mm, but read back %3. Nothing was recorded; check LinuxCNC&apos;s tool table before you cut.</source>
        <translation>已向 LinuxCNC 写入 T%1 的 TLO %2 mm，但读回的是：%3。未记录任何内容；切削前请检查 LinuxCNC 的刀具表。</translation>
    </message>
    <message>
        <source>The TLO</source>
        <translation>TLO</translation>
    </message>
    <message>
        <source>set a TLO for</source>
        <translation>设置 TLO</translation>
    </message>
    <message>
        <source>set a TLO</source>
        <translation>设置 TLO</translation>
    </message>
    <message>
        <source>The height above Z0</source>
        <translation>Z0 以上的高度</translation>
    </message>
    <message>
        <source>A TLO is restored for a tool, not for an empty spindle.</source>
        <translation>TLO 只能为刀具恢复，不能为空主轴恢复。</translation>
    </message>
    <message>
        <source>restore a TLO</source>
        <translation>恢复 TLO</translation>
    </message>
    <message>
        <source>%1 (the TLO that puts the tip %2 mm above Z0, from where it is)</source>
        <translation>%1（以当前位置为准，使刀尖位于 Z0 以上 %2 mm 的 TLO）</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s tool table (%1) has no %2: G10 L1 cannot add a tool. Nothing was written: add them to LinuxCNC&apos;s table, or leave them out.</source>
        <translation>LinuxCNC 的刀具表（%1）中没有 %2：G10 L1 无法新增刀具。未写入任何内容：请将它们加入 LinuxCNC 的刀具表，或将其略去。</translation>
    </message>
    <message>
        <source>write LinuxCNC&apos;s table</source>
        <translation>写入 LinuxCNC 的刀具表</translation>
    </message>
    <message>
        <source>T%1 reads %2, not %3 mm</source>
        <translation>T%1 读回为 %2，而不是 %3 mm</translation>
    </message>
    <message>
        <source>LinuxCNC&apos;s table does not read back as written: %1. %2</source>
        <translation>LinuxCNC 的刀具表读回的内容与写入的不一致：%1。%2</translation>
    </message>
    <message>
        <source>The probe was already touching, or touched something, before it probed (the setter&apos;s input triggered on the way to it or where it started): check the setter, its cable and the safe height. Nothing was measured. (%1)</source>
        <translation>探测前探针已接触或碰到了东西（对刀仪输入在移动途中或起点就已触发）：请检查对刀仪、线缆和安全高度。未测量任何数据。（%1）</translation>
    </message>
    <message>
        <source>The probe was already touching at machine Z %1 mm, before it moved: the setter&apos;s input is triggered there. Check the setter, its cable and the safe height. Nothing was measured.</source>
        <translation>探针在移动前于机床 Z %1 mm 处已接触：对刀仪输入在该处已触发。请检查对刀仪、线缆和安全高度。未测量任何数据。</translation>
    </message>
    <message>
        <source>The probe met nothing down to machine Z %1 mm: is a tool in the spindle, and is the setter where its settings say? Nothing was measured.</source>
        <translation>探针一直到机床 Z %1 mm 都未接触到任何东西：主轴上是否装有刀具？对刀仪是否在设置所示的位置？未测量任何数据。</translation>
    </message>
    <message>
        <source>LinuxCNC reported the contact at machine Z %1 mm, outside the move from %2 to %3 mm. Nothing was written or recorded; check the tool setter&apos;s settings and the machine.</source>
        <translation>LinuxCNC 报告的接触点在机床 Z %1 mm，超出了从 %2 到 %3 mm 的移动范围。未写入或记录任何数据；请检查对刀仪设置和机床。</translation>
    </message>
    <message>
        <source>T%1 cannot be probed so: %2 Nothing was sent.</source>
        <translation>T%1 无法这样测量：%2 未发送任何内容。</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineConnection</name>
    <message>
        <source>Reading the offsets…</source>
        <translation>正在读取补偿…</translation>
    </message>
    <message>
        <source>the current tool</source>
        <translation>当前刀具</translation>
    </message>
    <message>
        <source>Probing %1…</source>
        <translation>正在对 %1 对刀…</translation>
    </message>
    <message>
        <source>Break-testing %1…</source>
        <translation>正在对 %1 进行断刀检测…</translation>
    </message>
    <message>
        <source>Setting %1&apos;s TLO…</source>
        <translation>正在设置 %1 的 TLO…</translation>
    </message>
    <message>
        <source>Restoring T%1…</source>
        <translation>正在恢复 T%1…</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>解锁</translation>
    </message>
    <message>
        <source>Reading the status…</source>
        <translation>正在读取状态…</translation>
    </message>
    <message>
        <source>Selecting T%1…</source>
        <translation>正在选择 T%1…</translation>
    </message>
    <message>
        <source>Changing to T%1…</source>
        <translation>正在换到 T%1…</translation>
    </message>
    <message>
        <source>Check the machine, then unlock it.</source>
        <translation>请检查机器，然后解锁。</translation>
    </message>
    <message>
        <source>The machine is halted (Alarm lock) and takes no command but Unlock. %1</source>
        <translation>机器已停机（Alarm lock），除解锁外不接受任何命令。%1</translation>
    </message>
    <message>
        <source>Emptying the spindle…</source>
        <translation>正在清空主轴…</translation>
    </message>
    <message>
        <source>an unknown tool</source>
        <translation>未知刀具</translation>
    </message>
    <message>
        <source>no tool</source>
        <translation>无刀具</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>Before &quot;%1&quot; the machine had %2 in the spindle with TLO %3; now it has %4 with TLO %5.</source>
        <translation>在“%1”之前，机器主轴中为 %2，刀长补偿 %3；现在为 %4，刀长补偿 %5。</translation>
    </message>
    <message>
        <source>Toffee cannot tell whether it ran. Nothing of it was recorded; check the machine and run it again.</source>
        <translation>Toffee 无法判断它是否已执行。未记录任何内容；请检查机器后重新执行。</translation>
    </message>
    <message>
        <source>It ran on the machine, at least in part, but the machine&apos;s confirmation was lost: nothing of it was recorded. Run it again to record it.</source>
        <translation>它已在机器上执行（至少部分执行），但机器的确认丢失了：未记录任何内容。请重新执行以记录。</translation>
    </message>
    <message>
        <source>Nothing changed on the machine: it did not run, or it measured exactly the length held before. Nothing of it was recorded; run it again.</source>
        <translation>机器上没有任何变化：它没有执行，或测得的长度与之前完全相同。未记录任何内容；请重新执行。</translation>
    </message>
    <message>
        <source>The machine holds no TLO now, as after a restart: Toffee cannot tell whether it ran. Nothing of it was recorded; check the tool in the spindle and measure it again.</source>
        <translation>机器现在没有刀长补偿，就像重启之后：Toffee 无法判断它是否已执行。未记录任何内容；请检查主轴中的刀具并重新测量。</translation>
    </message>
    <message>
        <source>as asked.</source>
        <translation>按要求断开。</translation>
    </message>
    <message>
        <source>Reading the controller&apos;s tool table…</source>
        <translation>正在读取控制器的刀具表…</translation>
    </message>
    <message>
        <source>Writing the controller&apos;s tool table…</source>
        <translation>正在写入控制器的刀具表…</translation>
    </message>
    <message>
        <source>%1 answered as %2, not as %3 as chosen. Nothing of %3&apos;s was sent. Choose %2, or Automatic (toffee-cli --controller %4, or auto), and connect again.</source>
        <translation>%1 以 %2 的方式回答，而不是所选的 %3。未发送任何 %3 专用命令。请选择 %2 或“自动”（toffee-cli --controller %4 或 auto），然后重新连接。</translation>
    </message>
    <message>
        <source>It said: &quot;%1&quot;. </source>
        <translation>机器报告：“%1”。</translation>
    </message>
    <message>
        <source>Jogging…</source>
        <translation>点动中…</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineController</name>
    <message>
        <source>%1 keeps no tool table of its own: its tools&apos; TLOs are Toffee&apos;s table&apos;s alone.</source>
        <translation>%1 没有自己的刀具表：其刀具的 TLO 只保存在 Toffee 的刀具表中。</translation>
    </message>
    <message>
        <source>The link to %1 did not open within %2 s. Check the machine and the connection, then try again.</source>
        <translation>与 %1 的连接未能在 %2 秒内打开。请检查机器和连接后重试。</translation>
    </message>
    <message>
        <source>The break-test tolerance is not a number; enter a value such as 0.1 mm.</source>
        <translation>断刀检测公差不是数字；请输入例如 0.1 mm 的值。</translation>
    </message>
    <message>
        <source>A break-test tolerance of %1 mm is too small: the machine halts below %2 mm. Use %2 mm or more (%3 mm is the default).</source>
        <translation>断刀检测公差 %1 mm 太小：低于 %2 mm 时机床会停机。请使用 %2 mm 或以上（默认为 %3 mm）。</translation>
    </message>
    <message>
        <source>A break-test tolerance of %1 mm is larger than any tool.</source>
        <translation>断刀检测公差 %1 mm 比任何刀具都大。</translation>
    </message>
    <message>
        <source>%1 must be a number from -%2 to %2 mm.</source>
        <translation>%1 必须是 -%2 到 %2 mm 之间的数字。</translation>
    </message>
    <message>
        <source>Tool %1 is not a tool number; use %2 to %3 (%4 for an empty spindle).</source>
        <translation>刀具 %1 不是刀具号；请使用 %2 到 %3（%4 表示主轴为空）。</translation>
    </message>
    <message>
        <source>A tool change is already under way.</source>
        <translation>换刀已在进行中。</translation>
    </message>
    <message>
        <source>%1 on this machine: someone must be there to do it, but %2. Nothing was sent. Change the tool where someone can answer, or put it in by hand and select it.</source>
        <translation>%1（在这台机器上）：必须有人在场操作，但%2。未发送任何内容。请在有人可以应答的地方换刀，或手动装入刀具后选择它。</translation>
    </message>
    <message>
        <source>Nobody put T%1 in within the %2 s the change waits.</source>
        <translation>在换刀等待的 %2 秒内无人装入 T%1。</translation>
    </message>
    <message>
        <source>The change to T%1 was ended: nothing was measured or recorded. %2</source>
        <translation>换到 T%1 已结束：未测量也未记录任何内容。%2</translation>
    </message>
    <message>
        <source>The machine&apos;s reading makes T%1&apos;s TLO %2 mm, beyond any tool (%3 mm at most): nothing was recorded. Check the tool setter and the machine&apos;s reference, then probe again.</source>
        <translation>按机器的读数，T%1 的刀长补偿为 %2 mm，超出任何刀具（最多 %3 mm）：未记录任何内容。请检查对刀仪和机器的参考，然后重新测量。</translation>
    </message>
    <message>
        <source>%1 keeps its tool setter itself: Toffee does not jog it. Use the machine&apos;s own controls.</source>
        <translation>%1 自行管理对刀仪：Toffee 不对其点动。请使用机器自身的控制。</translation>
    </message>
    <message>
        <source>halt %1</source>
        <translation>停机 %1</translation>
    </message>
    <message>
        <source>The machine halted (reason %1).</source>
        <translation>机床已停机（原因 %1）。</translation>
    </message>
    <message>
        <source>Check the machine, then Unlock ($X).</source>
        <translation>检查机床，然后解锁（$X）。</translation>
    </message>
    <message>
        <source>T%1 measured %2 mm against its stored TLO %3 mm: %4 mm apart, more than the tolerance %5 mm. It may be broken or worn. The spindle is stopped and lifted; its stored TLO is kept in the table and in %6. Look at the tool and replace it before you cut.</source>
        <translation>T%1 测得 %2 mm，与其已存 TLO %3 mm 相差 %4 mm，超过公差 %5 mm。它可能已断裂或磨损。主轴已停止并抬起；其已存 TLO 保留在刀具表和 %6 中。切削前请检查刀具并更换。</translation>
    </message>
    <message>
        <source>Written before it: %1; not written: %2.</source>
        <translation>在此之前已写入：%1；未写入：%2。</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>无</translation>
    </message>
    <message>
        <source>This machine has no reference tool yet, so a new length cannot be compared. Probe a tool first: the first one measured becomes the reference.</source>
        <translation>这台机床还没有基准刀具，因此无法比较新的长度。请先对一把刀具对刀：第一把测量的刀具即成为基准。</translation>
    </message>
    <message>
        <source>T%1 has no stored TLO to compare with, in the table or in %2&apos;s own: probe it first.</source>
        <translation>T%1 没有可供比较的已存 TLO（刀具表和 %2 自己的表中都没有）：请先测量它。</translation>
    </message>
    <message>
        <source>T%1&apos;s edges differ by %2 mm (its limit %3 mm): runout or a chipped edge. Look at the cutter and how it sits in its holder before it cuts.</source>
        <translation>T%1 各刃相差 %2 mm（上限 %3 mm）：跳动或崩刃。切削前请检查刀具及其在刀柄中的安装。</translation>
    </message>
    <message>
        <source>T%1 is this machine&apos;s reference tool (its TLO is 0): every tool is measured against its contact at machine Z %2 mm.</source>
        <translation>T%1 是这台机床的基准刀具（其 TLO 为 0）：每把刀具都以它在机床 Z %2 mm 处的接触点为基准测量。</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineDock</name>
    <message>
        <source>Machine</source>
        <translation>机床</translation>
    </message>
    <message>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
    <message>
        <source>Probe</source>
        <translation>对刀</translation>
    </message>
    <message>
        <source>Set the offset by hand</source>
        <translation>手动设置补偿</translation>
    </message>
    <message>
        <source>Tool break test</source>
        <translation>断刀检测</translation>
    </message>
    <message>
        <source>What the machine&apos;s firmware cannot do</source>
        <translation>机床固件不支持的功能</translation>
    </message>
    <message>
        <source>%1: no break test (its M491.1 only re-measures) and no manual offset (it ignores M493.3).</source>
        <translation>%1：无断刀检测（其 M491.1 只会重新测量），也无手动补偿（它会忽略 M493.3）。</translation>
    </message>
    <message>
        <source>%1: no break test (Toffee cannot tell whether its M491.1 compares a tool with its TLO).</source>
        <translation>%1：无断刀检测（Toffee 无法判断其 M491.1 是否将刀具与其 TLO 比较）。</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineIdentity</name>
    <message>
        <source>the built-in emulator</source>
        <translation>内置模拟器</translation>
    </message>
    <message>
        <source>grblHAL “%1”</source>
        <translation>grblHAL“%1”</translation>
    </message>
    <message>
        <source>grblHAL at %1</source>
        <translation>位于 %1 的 grblHAL</translation>
    </message>
    <message>
        <source>the Carvera at %1</source>
        <translation>位于 %1 的 Carvera</translation>
    </message>
    <message>
        <source>the machine at %1</source>
        <translation>位于 %1 的机器</translation>
    </message>
    <message>
        <source>LinuxCNC at %1</source>
        <translation>位于 %1 的 LinuxCNC</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineLink</name>
    <message>
        <source>The machine did not answer &quot;%1&quot; within %2 s. The link was closed, because a late answer could be taken for the next command&apos;s. Reconnect, and check the machine before you go on.%3</source>
        <translation>机器未在 %2 秒内回应“%1”。连接已关闭，因为迟到的回应可能被当作下一条命令的回应。请重新连接，并在继续之前检查机器。%3</translation>
    </message>
    <message>
        <source>Not connected to the machine; connect first.</source>
        <translation>未连接到机床；请先连接。</translation>
    </message>
    <message>
        <source>The machine refused &quot;%1&quot;: %2</source>
        <translation>机床拒绝了“%1”：%2</translation>
    </message>
    <message>
        <source>the link was closed</source>
        <translation>连接已关闭</translation>
    </message>
    <message>
        <source>The connection to the machine was lost while it ran &quot;%1&quot;: %2</source>
        <translation>机床执行“%1”时连接丢失：%2</translation>
    </message>
    <message>
        <source>The connection to the machine was lost: %1</source>
        <translation>与机床的连接丢失：%1</translation>
    </message>
    <message>
        <source>The machine halted: %1</source>
        <translation>机床已停机：%1</translation>
    </message>
    <message>
        <source>Meanwhile it printed %1 lines that were no answer; only the last %2 were kept. A machine that prints that much is not well: check its firmware and the cable.</source>
        <translation>其间它输出了 %1 行非回应内容；只保留了最后 %2 行。输出如此之多的机器不正常：请检查其固件和电缆。</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineSession</name>
    <message>
        <source>The machine printed %1 lines before its answer; only the last %2 were kept, and the result may have been among the others.</source>
        <translation>机器在回应之前输出了 %1 行；只保留了最后 %2 行，结果可能在其余行中。</translation>
    </message>
    <message>
        <source>M493.2 T%1, then M493.3 Z%2</source>
        <translation>M493.2 T%1，然后 M493.3 Z%2</translation>
    </message>
    <message>
        <source>The machine sent no status report within 2 s, and the TLO in force is read from it. Nothing was recorded; check the cable or the Wi-Fi and try again.</source>
        <translation>机器在 2 秒内没有发送状态报告，而生效的刀长补偿要从中读取。未记录任何内容；请检查数据线或 Wi-Fi 后重试。</translation>
    </message>
    <message>
        <source>The machine&apos;s offset report (M493.4) holds values no machine can have: &quot;%1&quot;. Nothing was recorded; check the offsets on the machine before you cut.</source>
        <translation>机器的偏置报告（M493.4）含有任何机器都不可能有的数值：“%1”。未记录任何内容；切削前请在机器上检查偏置。</translation>
    </message>
    <message>
        <source>The machine&apos;s offset report (M493.4) could not be read%1. Nothing was recorded; try again, and check the cable or the Wi-Fi if it happens twice.</source>
        <translation>无法读取机器的偏置报告（M493.4）%1。未记录任何内容；请重试，若再次发生请检查数据线或 Wi-Fi。</translation>
    </message>
    <message>
        <source>The machine sent no status report within 2 s.</source>
        <translation>机床在 2 秒内没有发送状态报告。</translation>
    </message>
    <message>
        <source>The machine finished probing but its probe result ([PRB:…]) could not be read. Nothing was recorded; check the offsets (Report) before you cut.</source>
        <translation>机床已完成对刀，但无法读取对刀结果（[PRB:…]）。未记录任何内容；切削前请检查补偿（报告）。</translation>
    </message>
    <message>
        <source>The machine measured the tool, but its two reports disagree: the TLO in force is %1 mm, and its offset report does not add up to it. Nothing was recorded; probe again.</source>
        <translation>机床已测量刀具，但其两份报告不一致：生效的 TLO 为 %1 mm，而其偏置报告算不出此值。未记录任何内容；请重新对刀。</translation>
    </message>
    <message>
        <source>The firmware&apos;s break test takes T%1 for its wireless probe (T0, and every tool from T9 up): it would measure the tool, then halt. Break-test tools T1 to T8, or probe T%1 and compare its TLO with the table.</source>
        <translation>固件的断刀检测把 T%1 当作无线探头（T0 及 T9 以上的每把刀）：它会测量刀具然后停机。请只对 T1 到 T8 做断刀检测，或对 T%1 对刀并将其 TLO 与刀具表比较。</translation>
    </message>
    <message>
        <source>The stored TLO</source>
        <translation>已存 TLO</translation>
    </message>
    <message>
        <source>The machine sent no status report within 2 s; no break test was run.</source>
        <translation>机床在 2 秒内没有发送状态报告；未执行断刀检测。</translation>
    </message>
    <message>
        <source>The machine compared T%1 with a TLO of %2 mm, not its stored %3 mm, so its verdict does not hold. Check the offsets, then run the break test again.</source>
        <translation>机床将 T%1 与 %2 mm 的 TLO 比较，而不是其已存的 %3 mm，因此结论无效。请检查偏置，然后重新进行断刀检测。</translation>
    </message>
    <message>
        <source>Tool T%1 may be broken: it measured a TLO of %2 mm against %3 mm before (a difference of %4 mm; the tolerance is %5 mm). The machine has halted with the new length, %2 mm, in force. Check the tool and replace it if it is damaged, then Unlock: Toffee sets the stored TLO, %3 mm, back first.</source>
        <translation>刀具 T%1 可能已断：测得 TLO 为 %2 mm，之前为 %3 mm（相差 %4 mm；公差为 %5 mm）。机床已停机，新的长度 %2 mm 正在生效。请检查刀具，如有损坏请更换，然后解锁：Toffee 会先恢复已存的 TLO %3 mm。</translation>
    </message>
    <message>
        <source>The machine had no TLO for this tool to compare with: it measured the tool and took the new length without comparing. Check the TLO it reports against the table before you cut.</source>
        <translation>机床没有此刀具的 TLO 可供比较：它测量了刀具并在未比较的情况下采用了新长度。切削前请将其报告的 TLO 与刀具表核对。</translation>
    </message>
    <message>
        <source>The break test ran but its result (&quot;Old: … , new: …&quot;) could not be read. Run it again before you trust the tool.</source>
        <translation>断刀检测已运行，但无法读取其结果（“Old: … , new: …”）。在信任该刀具之前请重新运行。</translation>
    </message>
    <message>
        <source>Tool T%1 measured %2 mm against %3 mm, more than the %4 mm tolerance.</source>
        <translation>刀具 T%1 测得 %2 mm，之前为 %3 mm，超出了 %4 mm 的公差。</translation>
    </message>
    <message>
        <source>The machine was told TLO %1 mm but reports %2 mm in force. Check the offsets before you cut.</source>
        <translation>已向机床发送 TLO %1 mm，但其报告生效的是 %2 mm。切削前请检查偏置。</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>The tool length offset</source>
        <translation>刀具长度补偿</translation>
    </message>
    <message>
        <source>The height above Z0</source>
        <translation>Z0 以上的高度</translation>
    </message>
    <message>
        <source>The machine sent no status report within 2 s; its TLO was not set.</source>
        <translation>机床在 2 秒内没有发送状态报告；未设置其 TLO。</translation>
    </message>
    <message>
        <source>The machine finished changing to T%1, but its probe result ([PRB:…]) could not be read. Nothing was recorded; probe the tool again.</source>
        <translation>机床已换到 T%1，但无法读取其对刀结果（[PRB:…]）。未记录任何内容；请重新对刀。</translation>
    </message>
    <message>
        <source>The machine sent no status report within 2 s; it was not unlocked.</source>
        <translation>机床在 2 秒内没有发送状态报告；未解锁。</translation>
    </message>
    <message>
        <source>The machine was not halted.</source>
        <translation>机床并未停机。</translation>
    </message>
    <message>
        <source>The machine did not confirm the unlock; check its state before you go on.</source>
        <translation>机床未确认解锁；继续之前请检查其状态。</translation>
    </message>
    <message>
        <source>Unlocked. T%1&apos;s stored TLO, %2 mm, is in force again (the break test had left the new length in force).</source>
        <translation>已解锁。T%1 的已存 TLO %2 mm 重新生效（断刀检测曾使新长度生效）。</translation>
    </message>
    <message>
        <source>Unlocked, but the stored TLO (%1 mm) could not be set back: %2 The length the break test measured is still in force; do not cut.</source>
        <translation>已解锁，但无法恢复已存的 TLO（%1 mm）：%2 断刀检测测得的长度仍在生效；请勿切削。</translation>
    </message>
    <message>
        <source>The machine answered but sent no status report; is this a Carvera?</source>
        <translation>机床有回应，但没有发送状态报告；这是 Carvera 吗？</translation>
    </message>
    <message>
        <source>The machine did not answer &quot;%1&quot; within the %2 s allowed for connecting. Check that it is on, and the cable or the Wi-Fi, then connect again (or allow longer).</source>
        <translation>机器未在连接允许的 %2 秒内应答“%1”。请检查它是否已开机，以及数据线或 Wi-Fi，然后重新连接（或允许更长时间）。</translation>
    </message>
    <message>
        <source>The machine did not finish connecting within the %1 s allowed: it answered too slowly, or not at all. Check that it is on, and the cable or the Wi-Fi, then connect again (or allow longer).</source>
        <translation>机器未在允许的 %1 秒内完成连接：它应答太慢或根本没有应答。请检查它是否已开机，以及数据线或 Wi-Fi，然后重新连接（或允许更长时间）。</translation>
    </message>
    <message>
        <source>The machine stayed busy (%1) for the %2 s allowed for connecting. Wait for it to finish, or stop it, then connect again.</source>
        <translation>在连接允许的 %2 秒内机器一直忙碌（%1）。请等待其完成或将其停止，然后重新连接。</translation>
    </message>
    <message>
        <source>The machine was told to put its tool back, but it reports T%1 in the spindle. Check the spindle and the rack before you go on.</source>
        <translation>已让机床放回刀具，但它报告主轴上是 T%1。继续之前请检查主轴和刀库。</translation>
    </message>
    <message>
        <source>The machine was told to put its tool back but did not report an empty spindle. Check the spindle and the rack before you go on.</source>
        <translation>已让机床放回刀具，但它没有报告主轴为空。继续之前请检查主轴和刀库。</translation>
    </message>
    <message>
        <source>The machine runs %1: its M491.1 only measures the tool again and takes the new length without comparing, so a broken tool would pass. Probe the tool and compare its TLO with the table, or install the community firmware for break tests.</source>
        <translation>机床运行的是 %1：其 M491.1 只会重新测量刀具并直接采用新长度而不作比较，因此断刀也会通过。请对刀并将其 TLO 与刀具表比较，或安装社区固件以进行断刀检测。</translation>
    </message>
    <message>
        <source>The machine did not say which firmware it runs (%1), so Toffee cannot tell whether its M491.1 compares the tool or only measures it again. No break test was run; probe the tool and compare its TLO with the table.</source>
        <translation>机床未说明其运行的固件（%1），因此 Toffee 无法判断其 M491.1 是会比较刀具，还是只会重新测量。未执行断刀检测；请对刀并将其 TLO 与刀具表比较。</translation>
    </message>
    <message>
        <source>The machine runs %1, which ignores M493.3 without a word: a TLO set by hand would not be used. Probe the tool instead, or change to it with its TLO (a manual change).</source>
        <translation>机床运行的是 %1，它会不加提示地忽略 M493.3：手动设置的 TLO 不会被使用。请改为对刀，或带着其 TLO 换到该刀具（手动换刀）。</translation>
    </message>
    <message>
        <source>the tool in the spindle, which this firmware does not name, may be taken out by hand</source>
        <translation>主轴中的刀具（此固件不报告其编号）可能需手动取出</translation>
    </message>
    <message>
        <source>T%1 is taken out by hand</source>
        <translation>T%1 需手动取出</translation>
    </message>
    <message>
        <source>%1 and T%2 put in by hand</source>
        <translation>%1，并手动装入 T%2</translation>
    </message>
    <message>
        <source>T%1 is put in by hand</source>
        <translation>T%1 需手动装入</translation>
    </message>
    <message>
        <source>The machine halted to end it: check what is in the spindle, unlock it, then select the tool and probe it before cutting.</source>
        <translation>机器已停机以结束换刀：请检查主轴中的刀具，解锁机器，然后选择刀具并在切削前测量。</translation>
    </message>
    <message>
        <source>%1, which no Carvera does: this is another controller (grblHAL refuses it so). Nothing of the Carvera&apos;s was sent. Choose grblHAL, or Automatic, and connect again.</source>
        <translation>%1，任何 Carvera 都不会这样：这是另一种控制器（grblHAL 会这样拒绝）。未发送任何 Carvera 专用命令。请选择 grblHAL 或“自动”，然后重新连接。</translation>
    </message>
    <message>
        <source>The machine says the spindle is empty (T-1): a TLO set now would be kept by the firmware and given to whichever tool is selected next. Put the tool in and select it (Machine ▸ Select Tool, toffee-cli select-tool N), then set its TLO. Nothing was sent.</source>
        <translation>机器报告主轴为空（T-1）：此时设置的 TLO 会被固件保留，并赋给下一个选择的刀具。请先装入刀具并选择它（机器 ▸ 选择刀具，toffee-cli select-tool N），再设置其 TLO。未发送任何内容。</translation>
    </message>
    <message>
        <source>Unlocked. The TLO in force is %1 mm, as the machine left it: after a failed break test, the length the test measured. No stored TLO of T%2 was known here to set back (toffee-cli: --table FILE, or the history that recorded the test). Probe T%2, or set its TLO, before it cuts.</source>
        <translation>已解锁。当前生效的 TLO 为 %1 mm，即机器保留的值：断刀检测失败后，为检测测得的长度。此处不知道 T%2 存储的 TLO，无法恢复（toffee-cli：--table 文件，或记录该检测的历史）。切削前请测量 T%2 或设置其 TLO。</translation>
    </message>
    <message>
        <source>Makera&apos;s firmware measures a tool once, at the setter&apos;s centre (its M491 takes no R, X or Y): T%1&apos;s settings (%2) need the community firmware. Nothing was sent.</source>
        <translation>Makera 固件只在对刀仪中心测量一次（其 M491 不接受 R、X 或 Y）：T%1 的设置（%2）需要社区固件。未发送任何内容。</translation>
    </message>
    <message>
        <source>T%1 cannot be probed so: %2 Nothing was sent.</source>
        <translation>T%1 无法这样测量：%2 未发送任何内容。</translation>
    </message>
    <message>
        <source>Between its %1 touches the firmware lifts 25 mm for you to turn the cutter to its next edge by hand.</source>
        <translation>在 %1 次触碰之间，固件会抬起 25 mm，供您手动将刀具转到下一个刃。</translation>
    </message>
    <message>
        <source>The firmware touches at its own latch feed (atc.probe.slow_rate_mm_m in its config), not T%1&apos;s %2 mm/min.</source>
        <translation>固件使用其自身的慢速进给（配置中的 atc.probe.slow_rate_mm_m）触碰，而不是 T%1 的 %2 mm/min。</translation>
    </message>
    <message>
        <source>The firmware printed %1 of the %2 measurements it was asked for (M491 R%2). Nothing was recorded; check the offsets (Report) before you cut.</source>
        <translation>固件只输出了所要求的 %2 次测量中的 %1 次（M491 R%2）。未记录任何内容；切削前请检查偏置（报告）。</translation>
    </message>
    <message>
        <source>The firmware reported no reference tool offset, so its %1 measurements cannot be put in machine coordinates. Nothing was recorded.</source>
        <translation>固件未报告基准刀具偏置，因此其 %1 次测量无法换算为机床坐标。未记录任何内容。</translation>
    </message>
    <message>
        <source>Toffee set the longest edge&apos;s TLO (%2 mm) where the firmware kept the shortest&apos;s (%1 mm): no edge cuts deeper than the offset says.</source>
        <translation>固件保留了最短刃的 TLO（%1 mm），Toffee 已改设为最长刃的 TLO（%2 mm）：任何刃的切深都不会超过偏置所示。</translation>
    </message>
    <message>
        <source>The firmware&apos;s break test (M491.1) touches at the setter&apos;s centre only, and T%1 is measured off-centre: probe it (M491 with its settings) and compare the TLO with the table instead. Nothing was sent.</source>
        <translation>固件的断刀检测（M491.1）只在对刀仪中心触碰，而 T%1 需偏心测量：请改为测量它（按其设置使用 M491）并将 TLO 与刀具表比较。未发送任何内容。</translation>
    </message>
    <message>
        <source>The firmware&apos;s break test touched T%1 once, at one edge, not the %2 touches its settings ask for: probe it to compare every edge.</source>
        <translation>固件的断刀检测只在一个刃上触碰了 T%1 一次，而不是其设置要求的 %2 次：请测量它以比较每个刃。</translation>
    </message>
</context>
<context>
    <name>Toffee::MachineTableDialog</name>
    <message>
        <source>Open a machine&apos;s table</source>
        <translation>打开某台机床的刀具表</translation>
    </message>
    <message>
        <source>Open Machine Table</source>
        <translation>打开机床刀具表</translation>
    </message>
    <message>
        <source>Machine tables in %1:</source>
        <translation>%1 中的机床刀具表：</translation>
    </message>
    <message>
        <source>Library</source>
        <translation>刀具库</translation>
    </message>
    <message>
        <source>Machines</source>
        <translation>机床</translation>
    </message>
    <message>
        <source>Open or cancel</source>
        <translation>打开或取消</translation>
    </message>
    <message>
        <source>Open the machine&apos;s table</source>
        <translation>打开该机床的刀具表</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
</context>
<context>
    <name>Toffee::MainWindow</name>
    <message>
        <source>Tool tables (*.json *.tbl *.csv);;Toffee tool table (*.json);;LinuxCNC tool table (*.tbl);;CSV spreadsheet (*.csv);;All files (*)</source>
        <translation>刀具表 (*.json *.tbl *.csv);;Toffee 刀具表 (*.json);;LinuxCNC 刀具表 (*.tbl);;CSV 电子表格 (*.csv);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Cannot connect to the machine</source>
        <translation>无法连接到机床</translation>
    </message>
    <message>
        <source>Disconnected: %1</source>
        <translation>已断开：%1</translation>
    </message>
    <message>
        <source>1 tool</source>
        <translation>1 把刀具</translation>
    </message>
    <message>
        <source>%1 tools</source>
        <translation>%1 把刀具</translation>
    </message>
    <message>
        <source>Value not accepted</source>
        <translation>数值未被接受</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>Main</source>
        <translation>主工具栏</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>新建(&amp;N)</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>Import &amp;Tools…</source>
        <translation>导入刀具(&amp;T)…</translation>
    </message>
    <message>
        <source>&amp;Export…</source>
        <translation>导出(&amp;E)…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>撤销(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>重做(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Add Tool</source>
        <translation>添加刀具(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Remove Tool</source>
        <translation>删除刀具(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Filter…</source>
        <translation>筛选(&amp;F)…</translation>
    </message>
    <message>
        <source>%1 was changed by another program.

Reload it? Your unsaved changes in Toffee would be lost.</source>
        <translation>%1 已被其他程序修改。

重新加载？您在 Toffee 中未保存的更改将会丢失。</translation>
    </message>
    <message>
        <source>%1 was changed by another program.

Reload it?</source>
        <translation>%1 已被其他程序修改。

重新加载？</translation>
    </message>
    <message>
        <source>File changed on disk</source>
        <translation>磁盘上的文件已更改</translation>
    </message>
    <message>
        <source>Cannot reload the tool table</source>
        <translation>无法重新加载刀具表</translation>
    </message>
    <message>
        <source>The table on screen has not been changed.</source>
        <translation>屏幕上的表格未被更改。</translation>
    </message>
    <message>
        <source>Reloaded %1</source>
        <translation>已重新加载 %1</translation>
    </message>
    <message>
        <source>&amp;Machine</source>
        <translation>机床(&amp;M)</translation>
    </message>
    <message>
        <source>Machine</source>
        <translation>机床</translation>
    </message>
    <message>
        <source>&amp;Connect / Disconnect</source>
        <translation>连接 / 断开(&amp;C)</translation>
    </message>
    <message>
        <source>&amp;Probe Current Tool…</source>
        <translation>对当前刀具对刀(&amp;P)…</translation>
    </message>
    <message>
        <source>&amp;Break Test…</source>
        <translation>断刀检测(&amp;B)…</translation>
    </message>
    <message>
        <source>&amp;Unlock</source>
        <translation>解锁(&amp;U)</translation>
    </message>
    <message>
        <source>&amp;Stop the Machine</source>
        <translation>停止机床(&amp;S)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Dark Palette</source>
        <translation>深色配色(&amp;D)</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>Connecting to %1…</source>
        <translation>正在连接到 %1…</translation>
    </message>
    <message>
        <source>connected</source>
        <translation>已连接</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <source>Cannot open the tool table</source>
        <translation>无法打开刀具表</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>已打开 %1</translation>
    </message>
    <message>
        <source>Open Tool Table</source>
        <translation>打开刀具表</translation>
    </message>
    <message>
        <source>Save as %1?</source>
        <translation>另存为 %1？</translation>
    </message>
    <message>
        <source>Cannot save the tool table</source>
        <translation>无法保存刀具表</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <source>Save Tool Table</source>
        <translation>保存刀具表</translation>
    </message>
    <message>
        <source>Import Tools</source>
        <translation>导入刀具</translation>
    </message>
    <message>
        <source>Cannot import</source>
        <translation>无法导入</translation>
    </message>
    <message>
        <source>Nothing was imported.</source>
        <translation>未导入任何内容。</translation>
    </message>
    <message>
        <source>Imported %1 tools from %2</source>
        <translation>已从 %2 导入 %1 把刀具</translation>
    </message>
    <message>
        <source>Export Tool Table</source>
        <translation>导出刀具表</translation>
    </message>
    <message>
        <source>Cannot export</source>
        <translation>无法导出</translation>
    </message>
    <message>
        <source>Exported to %1</source>
        <translation>已导出到 %1</translation>
    </message>
    <message>
        <source>Cannot add a tool</source>
        <translation>无法添加刀具</translation>
    </message>
    <message>
        <source>Every tool number is in use.</source>
        <translation>所有刀具号都已被使用。</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>未保存的更改</translation>
    </message>
    <message>
        <source>The tool table has changes that are not saved.
Save them first?</source>
        <translation>刀具表有未保存的更改。
先保存吗？</translation>
    </message>
    <message>
        <source>The machine is busy</source>
        <translation>机床正忙</translation>
    </message>
    <message>
        <source>The machine is running &quot;%1&quot;. Stop it and quit?</source>
        <translation>机床正在执行“%1”。停止并退出吗？</translation>
    </message>
    <message>
        <source>Export for &amp;Controller…</source>
        <translation>为控制器导出(&amp;C)…</translation>
    </message>
    <message>
        <source>Recover Unsaved Edits</source>
        <translation>恢复未保存的修改</translation>
    </message>
    <message>
        <source>Toffee stopped before a new table was saved. Its last copy is from %1.</source>
        <translation>Toffee 在新表保存之前停止了。其最后一份副本来自 %1。</translation>
    </message>
    <message>
        <source>Toffee stopped before the edits to %1 were saved. Their last copy is from %2.</source>
        <translation>Toffee 在对 %1 的修改保存之前停止了。其最后一份副本来自 %2。</translation>
    </message>
    <message>
        <source>The copy holds %1 tools. Recover puts it on top of the file as it is on disk, unsaved: review it, then save; Undo shows the file as it was. Discard deletes the copy; Later keeps it for the next start.</source>
        <translation>副本包含 %1 把刀具。“恢复”会把它叠加在磁盘上的文件之上，且不保存：请检查后再保存；“撤销”可显示文件原来的样子。“放弃”会删除副本；“稍后”会保留到下次启动。</translation>
    </message>
    <message>
        <source>&amp;Recover</source>
        <translation>恢复(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;Later</source>
        <translation>稍后(&amp;L)</translation>
    </message>
    <message>
        <source>Unsaved edits are not protected against a crash until they are saved: %1</source>
        <translation>在保存之前，未保存的修改不受崩溃保护：%1</translation>
    </message>
    <message>
        <source>Recovered unsaved edits: review them, then save.</source>
        <translation>已恢复未保存的修改：请检查后保存。</translation>
    </message>
    <message>
        <source>Some copies of unsaved edits could not be read (%1 in all), so they cannot be recovered.</source>
        <translation>有些未保存修改的副本无法读取（共 %1 个），因此无法恢复。</translation>
    </message>
    <message>
        <source>Copies moved to %2, never to be offered again: %1.</source>
        <translation>已移至 %2、不会再次提供的副本：%1 个。</translation>
    </message>
    <message>
        <source>Copies that could not be moved to %2 and were left, untouched, in %3 (look at them there, or remove them by hand): %1.</source>
        <translation>无法移至 %2、因此原样留在 %3 的副本（请在那里查看，或手动删除）：%1 个。</translation>
    </message>
    <message>
        <source>Nothing else was changed.</source>
        <translation>其他内容均未更改。</translation>
    </message>
    <message>
        <source>Machine State</source>
        <translation>机床状态</translation>
    </message>
    <message>
        <source>T%1 shares pocket %2 with %3. LinuxCNC&apos;s random tool changer needs each tool in its own pocket.</source>
        <translation>T%1 与 %3 共用刀位 %2。LinuxCNC 的随机换刀装置要求每把刀具都有自己的刀位。</translation>
    </message>
    <message>
        <source>halted</source>
        <translation>已停机</translation>
    </message>
    <message>
        <source>After saving, the table on screen shows what the file holds; until the window is closed, Undo brings the rest back. To keep everything, Cancel and use Save As with a .json file.

Save anyway?</source>
        <translation>保存后，屏幕上的表格显示文件中保存的内容；在关闭窗口之前，撤销可以恢复其余内容。若要保留全部内容，请取消并使用“另存为”保存为 .json 文件。

仍然保存？</translation>
    </message>
    <message>
        <source>The history library cannot be written: %1 Measurements wait here and are written as soon as it can be.</source>
        <translation>无法写入历史库：%1 测量结果在此等待，一旦可以写入就会写入。</translation>
    </message>
    <message>
        <source>The history library is written again: every waiting measurement is in it.</source>
        <translation>历史库已恢复写入：所有等待的测量结果都已写入。</translation>
    </message>
    <message>
        <source>Export History</source>
        <translation>导出历史</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV（*.csv）</translation>
    </message>
    <message>
        <source>The history was not exported</source>
        <translation>历史未导出</translation>
    </message>
    <message>
        <source>Exported %1 measurements to %2</source>
        <translation>已将 %1 条测量记录导出到 %2</translation>
    </message>
    <message>
        <source>&amp;Record a Program Run…</source>
        <translation>记录程序运行(&amp;R)…</translation>
    </message>
    <message>
        <source>Record a Program Run</source>
        <translation>记录程序运行</translation>
    </message>
    <message>
        <source>G-code programs (*.nc *.gcode *.ngc *.tap *.cnc);;All files (*)</source>
        <translation>G 代码程序 (*.nc *.gcode *.ngc *.tap *.cnc);;所有文件 (*)</translation>
    </message>
    <message>
        <source>The program run was not recorded</source>
        <translation>程序运行未被记录</translation>
    </message>
    <message>
        <source>Recorded the cutting time of %1 tools from %2.</source>
        <translation>已记录 %2 中 %1 把刀具的切削时间。</translation>
    </message>
    <message>
        <source>History &amp;Library…</source>
        <translation>历史库(&amp;L)…</translation>
    </message>
    <message>
        <source>Tool tables and CAM libraries (*.json *.tbl *.csv *.tools *.hsmlib *.nc *.gcode *.cnc *.ngc *.tap *.txt);;Toffee tool table (*.json);;LinuxCNC tool table (*.tbl);;CSV spreadsheet (*.csv);;Fusion tool library (*.json *.tools);;HSM tool library (*.hsmlib);;Makera CAM program (*.nc *.gcode *.cnc *.ngc *.tap *.txt);;All files (*)</source>
        <translation>刀具表和 CAM 刀具库 (*.json *.tbl *.csv *.tools *.hsmlib *.nc *.gcode *.cnc *.ngc *.tap *.txt);;Toffee 刀具表 (*.json);;LinuxCNC 刀具表 (*.tbl);;CSV 电子表格 (*.csv);;Fusion 刀具库 (*.json *.tools);;HSM 刀具库 (*.hsmlib);;Makera CAM 程序 (*.nc *.gcode *.cnc *.ngc *.tap *.txt);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Import tools from %1</source>
        <translation>从 %1 导入刀具</translation>
    </message>
    <message>
        <source>Imported from %1: %2</source>
        <translation>已从 %1 导入：%2</translation>
    </message>
    <message>
        <source>Check &amp;Job…</source>
        <translation>检查作业(&amp;J)…</translation>
    </message>
    <message>
        <source>Check Job</source>
        <translation>检查作业</translation>
    </message>
    <message>
        <source>G-code programs (*.nc *.gcode *.ngc *.tap *.cnc *.gc *.g *.pgm *.mpf);;All files (*)</source>
        <translation>G 代码程序 (*.nc *.gcode *.ngc *.tap *.cnc *.gc *.g *.pgm *.mpf);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Rack</source>
        <translation>刀库</translation>
    </message>
    <message>
        <source>The shared library cannot be used</source>
        <translation>无法使用共享刀具库</translation>
    </message>
    <message>
        <source>Open &amp;Machine Table…</source>
        <translation>打开机床刀具表(&amp;M)…</translation>
    </message>
    <message>
        <source>Save to &amp;Library…</source>
        <translation>保存到刀具库(&amp;L)…</translation>
    </message>
    <message>
        <source>Open Machine Table</source>
        <translation>打开机床刀具表</translation>
    </message>
    <message>
        <source>The library (%1) is not open, so its machine tables cannot be listed: %2</source>
        <translation>刀具库（%1）未打开，因此无法列出其中的机床刀具表：%2</translation>
    </message>
    <message>
        <source>The library (%1) holds no machine tables yet. File ▸ Save to Library… puts the open table there as a machine&apos;s table.</source>
        <translation>刀具库（%1）中还没有机床刀具表。“文件 ▸ 保存到刀具库…”会将当前打开的刀具表作为某台机床的刀具表存入其中。</translation>
    </message>
    <message>
        <source>The library (%1) is not open: %2</source>
        <translation>刀具库（%1）未打开：%2</translation>
    </message>
    <message>
        <source>Cannot open the machine&apos;s table</source>
        <translation>无法打开该机床的刀具表</translation>
    </message>
    <message>
        <source>Opened %1&apos;s table from %2</source>
        <translation>已从 %2 打开 %1 的刀具表</translation>
    </message>
    <message>
        <source>Cannot save to the library</source>
        <translation>无法保存到刀具库</translation>
    </message>
    <message>
        <source>The machine&apos;s name in the library</source>
        <translation>机床在刀具库中的名称</translation>
    </message>
    <message>
        <source>Save to Library</source>
        <translation>保存到刀具库</translation>
    </message>
    <message>
        <source>Save this table in %1 as the table of the machine:</source>
        <translation>将此刀具表保存到 %1，作为以下机床的刀具表：</translation>
    </message>
    <message>
        <source>Nothing was written to the library.</source>
        <translation>未向刀具库写入任何内容。</translation>
    </message>
    <message>
        <source>Saved as %1&apos;s table in %2</source>
        <translation>已作为 %1 的刀具表保存到 %2</translation>
    </message>
    <message>
        <source>This table came from %1, and the window now works with %2. Use Save As to keep it in a file, or choose %1 again in Machine ▸ History Library….</source>
        <translation>此刀具表来自 %1，而窗口现在使用的是 %2。请用“另存为”将其保存到文件中，或在“机床 ▸ 历史库…”中重新选择 %1。</translation>
    </message>
    <message>
        <source>Nothing was written: the table on screen keeps your changes.</source>
        <translation>未写入任何内容：屏幕上的刀具表保留您的修改。</translation>
    </message>
    <message>
        <source>The library cannot be reached: your changes are kept on this station and written when it is back.</source>
        <translation>无法连接刀具库：您的修改保存在本工作站上，待刀具库恢复后再写入。</translation>
    </message>
    <message>
        <source>Saved 1 tool to %1&apos;s table in %2</source>
        <translation>已将 1 把刀具保存到 %2 中 %1 的刀具表</translation>
    </message>
    <message>
        <source>Saved %1 tools to %2&apos;s table in %3</source>
        <translation>已将 %1 把刀具保存到 %3 中 %2 的刀具表</translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation>%1 — %2</translation>
    </message>
    <message>
        <source>%1 (read-only)</source>
        <translation>%1（只读）</translation>
    </message>
    <message>
        <source>Read-only: your role may read this library but not change it. Whoever runs the server can give it write rights.</source>
        <translation>只读：您的角色可以读取此刀具库，但不能更改。服务器的管理员可以为其授予写入权限。</translation>
    </message>
    <message>
        <source>Read-only: the library file %1 cannot be written, so this table can be read but not changed.</source>
        <translation>只读：库文件 %1 无法写入，因此此刀具表只能读取，不能更改。</translation>
    </message>
    <message>
        <source>another station</source>
        <translation>另一工作站</translation>
    </message>
    <message>
        <source>T%1 was changed on %2</source>
        <translation>T%1 已在 %2 上被更改</translation>
    </message>
    <message>
        <source>your edit is kept — Save to choose.</source>
        <translation>您的修改已保留 — 保存时再作选择。</translation>
    </message>
    <message>
        <source>your edits are kept — Save to choose.</source>
        <translation>您的修改已保留 — 保存时再作选择。</translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation>未保存：%1</translation>
    </message>
    <message>
        <source>Changed on Another Station While the Library Was Offline</source>
        <translation>刀具库离线期间在另一工作站上被更改</translation>
    </message>
    <message>
        <source>%1&apos;s table keeps the other station&apos;s tools.</source>
        <translation>%1 的刀具表保留另一工作站的刀具。</translation>
    </message>
    <message>
        <source>Toffee records into this station&apos;s own library (%1) until the shared one is fixed (Machine ▸ History Library…).</source>
        <translation>在共享刀具库修复之前（机床 ▸ 历史库…），Toffee 会记录到本工作站自己的库（%1）中。</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>&amp;About Toffee</source>
        <translation>关于 Toffee(&amp;A)</translation>
    </message>
    <message>
        <source>Connected again</source>
        <translation>已重新连接</translation>
    </message>
    <message>
        <source>The link to the machine was lost</source>
        <translation>与机器的连接已断开</translation>
    </message>
    <message>
        <source>The link to the machine was lost during &quot;%1&quot;: %2</source>
        <translation>在“%1”期间与机器的连接断开：%2</translation>
    </message>
    <message>
        <source>Nothing of it was written to the tool table or the history: the machine did not confirm it. Reconnect to read the machine&apos;s offsets back; Toffee then says whether it happened.</source>
        <translation>未向刀具表或历史写入任何内容：机器没有确认。请重新连接以读回机器的偏置；Toffee 随后会告知它是否已执行。</translation>
    </message>
    <message>
        <source>Reconnect</source>
        <translation>重新连接</translation>
    </message>
    <message>
        <source>Not Now</source>
        <translation>暂不</translation>
    </message>
    <message>
        <source>The link to the machine was lost: %1</source>
        <translation>与机器的连接已断开：%1</translation>
    </message>
    <message>
        <source>Nothing was running. Reconnect to read the machine&apos;s tool and TLO again.</source>
        <translation>当时没有正在执行的操作。请重新连接以再次读取机器的刀具和刀长补偿。</translation>
    </message>
    <message>
        <source>Remove T%1?</source>
        <translation>移除 T%1？</translation>
    </message>
    <message>
        <source>Remove %1 tools?</source>
        <translation>移除 %1 把刀具？</translation>
    </message>
    <message>
        <source>%1 has a measured TLO, which goes with it from the table (the history keeps its measurements).</source>
        <translation>%1 有已测量的刀长补偿，将随之从刀具表中移除（历史记录会保留其测量）。</translation>
    </message>
    <message>
        <source>Edit ▸ Undo brings it back.</source>
        <translation>编辑 ▸ 撤销 可以恢复。</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <source>R&amp;ack</source>
        <translation>刀库(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Measure Rack…</source>
        <translation>测量刀库(&amp;M)…</translation>
    </message>
    <message>
        <source>&amp;Check Rack…</source>
        <translation>检查刀库(&amp;C)…</translation>
    </message>
    <message>
        <source>Tool &amp;Setter…</source>
        <translation>对刀仪(&amp;S)…</translation>
    </message>
    <message>
        <source>Push &amp;Offsets to the Controller…</source>
        <translation>向控制器推送补偿(&amp;O)…</translation>
    </message>
    <message>
        <source>P&amp;ull Offsets from the Controller…</source>
        <translation>从控制器拉取补偿(&amp;U)…</translation>
    </message>
    <message>
        <source>For a controller that keeps a tool table of its own (grblHAL): connect to one first.</source>
        <translation>适用于自带刀具表的控制器（grblHAL）：请先连接一台。</translation>
    </message>
    <message>
        <source>The tool setter is kept on this computer only: %1</source>
        <translation>对刀仪设置仅保存在这台计算机上：%1</translation>
    </message>
    <message>
        <source>%1&apos;s tool setter: X %2, Y %3, lowest Z %4 mm.</source>
        <translation>%1 的对刀仪：X %2，Y %3，最低 Z %4 mm。</translation>
    </message>
    <message>
        <source>Cannot read the controller&apos;s tool table</source>
        <translation>无法读取控制器的刀具表</translation>
    </message>
    <message>
        <source>beyond its table (T1 to T%1)</source>
        <translation>超出其刀具表（T1 到 T%1）</translation>
    </message>
    <message>
        <source>unchanged</source>
        <translation>未更改</translation>
    </message>
    <message>
        <source>written</source>
        <translation>已写入</translation>
    </message>
    <message>
        <source>The offsets were not all pushed</source>
        <translation>并非所有补偿都已推送</translation>
    </message>
    <message>
        <source>empty in the controller: left alone</source>
        <translation>控制器中为空：保持不变</translation>
    </message>
    <message>
        <source>taken, as set on the controller</source>
        <translation>已采用，按控制器中的设置</translation>
    </message>
    <message>
        <source>new tool</source>
        <translation>新刀具</translation>
    </message>
    <message>
        <source>Pull Offsets from %1</source>
        <translation>从 %1 拉取补偿</translation>
    </message>
    <message>
        <source>Taken from the controller&apos;s table into the file: %1 TLOs.</source>
        <translation>已从控制器的刀具表采用到文件中：%1 个 TLO。</translation>
    </message>
    <message>
        <source>New &amp;Cutter…</source>
        <translation>新刀具(&amp;C)…</translation>
    </message>
    <message>
        <source>Select the one tool whose cutter was changed.</source>
        <translation>请选择更换了刀具的那一把。</translation>
    </message>
    <message>
        <source>its TLO %1 %2 (%3)</source>
        <translation>其 TLO %1 %2（%3）</translation>
    </message>
    <message>
        <source>set by hand</source>
        <translation>手动设置</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>已测量</translation>
    </message>
    <message>
        <source>its wear (length %1, radius %2)</source>
        <translation>其磨损（长度 %1，半径 %2）</translation>
    </message>
    <message>
        <source>its broken mark</source>
        <translation>其断刀标记</translation>
    </message>
    <message>
        <source>its used life</source>
        <translation>其已用寿命</translation>
    </message>
    <message>
        <source>New cutter in T%1?</source>
        <translation>T%1 换新刀具？</translation>
    </message>
    <message>
        <source>T%1 gets a new cutter. Measure it on the tool setter before it cuts.</source>
        <translation>T%1 换上新刀具。切削前请在对刀仪上测量。</translation>
    </message>
    <message>
        <source>T%1 gets a new cutter: %2 belong to the old one and end here (the history keeps them as the old cutter&apos;s). Measure T%1 on the tool setter before it cuts.</source>
        <translation>T%1 换上新刀具：%2 属于旧刀具，至此结束（历史记录将其作为旧刀具的数据保留）。切削前请在对刀仪上测量 T%1。</translation>
    </message>
    <message>
        <source>New Cutter</source>
        <translation>新刀具</translation>
    </message>
    <message>
        <source>Cannot put in a new cutter</source>
        <translation>无法换上新刀具</translation>
    </message>
    <message>
        <source>T%1 has a new cutter: measure it before it cuts.</source>
        <translation>T%1 已换新刀具：切削前请测量。</translation>
    </message>
    <message>
        <source>Which unit?</source>
        <translation>哪种单位？</translation>
    </message>
    <message>
        <source>Millimetres</source>
        <translation>毫米</translation>
    </message>
    <message>
        <source>Inches</source>
        <translation>英寸</translation>
    </message>
    <message>
        <source>This table is read-only here, so a measurement could not be kept in it. Open a table you may change to probe, set or test tools.</source>
        <translation>此刀具表在这里为只读，测量结果无法保存在其中。要对刀具进行测量、设置或检测，请打开您可以修改的刀具表。</translation>
    </message>
    <message>
        <source>Edit ▸ Undo puts the old values back in the table; the history keeps that a new cutter went in, and the job check warns of a TLO from before it.</source>
        <translation>编辑 ▸ 撤销会把旧值放回表中；历史记录仍保留换了新刀具这一事实，作业检查会对此前的 TLO 发出警告。</translation>
    </message>
    <message>
        <source>Tools in %2 without a unit (Fusion writes &quot;unit&quot; on every tool): %1. Their diameters and lengths are read in the unit you choose; the preview shows each of them before anything changes.</source>
        <translation>%2 中没有单位的刀具（Fusion 会为每把刀具写入 &quot;unit&quot;）：%1。其直径和长度将按您选择的单位读取；在任何更改之前，预览会逐一显示。</translation>
    </message>
    <message>
        <source>The offsets were not pulled</source>
        <translation>未拉取补偿</translation>
    </message>
    <message>
        <source>“%1” is %2, new to the history library.</source>
        <translation>“%1”是%2，在历史库中是新的。</translation>
    </message>
    <message>
        <source>Another machine under this name</source>
        <translation>此名称下的另一台机器</translation>
    </message>
    <message>
        <source>“%1” in the history library is %2; this is %3.</source>
        <translation>历史库中的“%1”是%2；这是%3。</translation>
    </message>
    <message>
        <source>A machine&apos;s reference, tool setter and history are its own. If this is the same machine reached another way, say so; if not, give it a name of its own (Machine ▸ History Library…, Machine name) and connect again.</source>
        <translation>机器的参考、对刀仪和历史只属于它自己。如果这是通过其他方式连接的同一台机器，请说明；否则请为它起一个自己的名称（机床 ▸ 历史库…，机器名称），然后重新连接。</translation>
    </message>
    <message>
        <source>Same Machine</source>
        <translation>同一台机器</translation>
    </message>
    <message>
        <source>Not connected: “%1” in the history library is %2, not %3. Give this machine a name of its own (Machine ▸ History Library…, Machine name), then connect again.</source>
        <translation>未连接：历史库中的“%1”是%2，而不是%3。请为这台机器起一个自己的名称（机床 ▸ 历史库…，机器名称），然后重新连接。</translation>
    </message>
    <message>
        <source>“%1” was %2 before; now it is %3.</source>
        <translation>“%1”之前是%2；现在是%3。</translation>
    </message>
    <message>
        <source>The selected tool&apos;s pocket holds another cutter: its TLO, length, wear and break mark end, and it is measured before it cuts</source>
        <translation>所选刀具的刀位装了另一把刀具：其 TLO、长度、磨损和断刀标记作废，切削前需先测量</translation>
    </message>
    <message>
        <source>its length %1 %2</source>
        <translation>其长度 %1 %2</translation>
    </message>
    <message>
        <source>read from the controller</source>
        <translation>从控制器读取</translation>
    </message>
    <message>
        <source>User&apos;s &amp;Guide</source>
        <translation>用户指南(&amp;G)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>The System&apos;s</source>
        <translation>跟随系统</translation>
    </message>
    <message>
        <source>The window speaks %1 from its next start.</source>
        <translation>窗口将从下次启动起使用%1。</translation>
    </message>
    <message>
        <source>the system&apos;s language</source>
        <translation>系统语言</translation>
    </message>
    <message>
        <source>not in its table</source>
        <translation>不在其刀具表中</translation>
    </message>
    <message>
        <source>%1 cannot go into %2&apos;s table of %3 tools: nothing is pushed. Renumber them, or remove their TLOs, and push again.</source>
        <translation>%1 无法放入 %2 的刀具表（共 %3 把刀具）：未推送任何内容。请为它们重新编号，或删除它们的 TLO，然后再次推送。</translation>
    </message>
    <message>
        <source>%1 are not in %2&apos;s tool table, and G10 L1 cannot add a tool: nothing is pushed. Add them to its table, or remove their TLOs, and push again.</source>
        <translation>%1 不在 %2 的刀具表中，而 G10 L1 无法新增刀具：未推送任何内容。请将它们加入其刀具表，或删除它们的 TLO，然后再次推送。</translation>
    </message>
    <message>
        <source>Written into %1&apos;s table and read back, all agreeing: %2 TLOs.</source>
        <translation>已写入 %1 的刀具表并读回，全部一致：%2 个 TLO。</translation>
    </message>
    <message>
        <source>&amp;LinuxCNC Access…</source>
        <translation>LinuxCNC 访问(&amp;L)…</translation>
    </message>
    <message>
        <source>this machine</source>
        <translation>本机床</translation>
    </message>
    <message>
        <source>The LinuxCNC access is kept on this computer; it applies from the next connection.</source>
        <translation>LinuxCNC 访问设置保存在本机；从下一次连接起生效。</translation>
    </message>
</context>
<context>
    <name>Toffee::OffsetEditor</name>
    <message>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <source>How to set the offset</source>
        <translation>补偿的设置方式</translation>
    </message>
    <message>
        <source>Set TLO to</source>
        <translation>将 TLO 设为</translation>
    </message>
    <message>
        <source>Change TLO by</source>
        <translation>将 TLO 改变</translation>
    </message>
    <message>
        <source>Gauge height above Z0</source>
        <translation>Z0 以上的量规高度</translation>
    </message>
    <message>
        <source>Offset value in millimetres</source>
        <translation>补偿值（毫米）</translation>
    </message>
    <message>
        <source>Command that will be sent</source>
        <translation>将要发送的命令</translation>
    </message>
    <message>
        <source>Resulting tool length offset</source>
        <translation>得到的刀具长度补偿</translation>
    </message>
    <message>
        <source>Send the offset to the machine</source>
        <translation>把补偿发送到机床</translation>
    </message>
    <message>
        <source>Send the command above — Ctrl+Enter</source>
        <translation>发送上面的命令 — Ctrl+Enter</translation>
    </message>
    <message>
        <source>Sends:</source>
        <translation>发送：</translation>
    </message>
    <message>
        <source>TLO:</source>
        <translation>TLO：</translation>
    </message>
    <message>
        <source>(the current TLO is not known yet)</source>
        <translation>（当前 TLO 尚未知道）</translation>
    </message>
    <message>
        <source>%1 → set by the machine from the spindle&apos;s position</source>
        <translation>%1 → 由机床根据主轴位置设置</translation>
    </message>
    <message>
        <source>The offset was not set</source>
        <translation>补偿未被设置</translation>
    </message>
    <message>
        <source>Change %1&apos;s tool length offset?</source>
        <translation>更改 %1 的刀具长度补偿？</translation>
    </message>
    <message>
        <source>Send %1 for %2?
TLO %3

The next cut uses the new offset. The table records it as set by hand, not measured.</source>
        <translation>为 %2 发送 %1？
TLO %3

下一次切削将使用新的补偿。刀具表会将其记录为手动设置，而非测量值。</translation>
    </message>
    <message>
        <source>Nothing was written to the tool table.</source>
        <translation>刀具表中未写入任何内容。</translation>
    </message>
    <message>
        <source>the machine reports no tool in the spindle.</source>
        <translation>机床报告主轴上没有刀具。</translation>
    </message>
    <message>
        <source>The offset is set but not recorded</source>
        <translation>补偿已设置但未记录</translation>
    </message>
    <message>
        <source>The machine now has TLO %1, but the table could not record it: %2</source>
        <translation>机床现在的 TLO 为 %1，但刀具表无法记录：%2</translation>
    </message>
</context>
<context>
    <name>Toffee::OffsetSyncDialog</name>
    <message>
        <source>Push Offsets to %1</source>
        <translation>向 %1 推送补偿</translation>
    </message>
    <message>
        <source>Pull Offsets from %1</source>
        <translation>从 %1 拉取补偿</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>刀具</translation>
    </message>
    <message>
        <source>TLO in the file</source>
        <translation>文件中的 TLO</translation>
    </message>
    <message>
        <source>TLO in %1</source>
        <translation>%1 中的 TLO</translation>
    </message>
    <message>
        <source>Pushing</source>
        <translation>推送</translation>
    </message>
    <message>
        <source>Pulling</source>
        <translation>拉取</translation>
    </message>
    <message>
        <source>Nothing to change: the file and %1 agree.</source>
        <translation>无需更改：文件与 %1 一致。</translation>
    </message>
    <message>
        <source>The TLOs in bold (%1) will be written into %2&apos;s own table and read back. The file does not change.</source>
        <translation>粗体的 TLO（%1）将写入 %2 自身的刀具表并读回。文件不会更改。</translation>
    </message>
    <message>
        <source>The TLOs in bold (%1) will be taken into the file as set on %2, not measured by Toffee, each with a history event. %2 does not change.</source>
        <translation>粗体的 TLO（%1）将按 %2 中的设置采用到文件中，而非由 Toffee 测得，每个都附带一条历史记录。%2 不会更改。</translation>
    </message>
    <message>
        <source>&amp;Push</source>
        <translation>推送(&amp;P)</translation>
    </message>
    <message>
        <source>P&amp;ull</source>
        <translation>拉取(&amp;U)</translation>
    </message>
</context>
<context>
    <name>Toffee::ProbePanel</name>
    <message>
        <source>Probe Current Tool</source>
        <translation>对当前刀具对刀</translation>
    </message>
    <message>
        <source>Restore Known TLO</source>
        <translation>恢复已知 TLO</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Probe the current tool on the tool setter</source>
        <translation>在对刀仪上测量当前刀具</translation>
    </message>
    <message>
        <source>Measure the tool in the spindle on the tool setter (M491) — F5</source>
        <translation>在对刀仪上测量主轴中的刀具（M491）— F5</translation>
    </message>
    <message>
        <source>Restore the selected tool&apos;s known TLO</source>
        <translation>恢复所选刀具的已知 TLO</translation>
    </message>
    <message>
        <source>Make the selected tool active with the TLO measured before, without probing — Ctrl+R</source>
        <translation>以之前测得的 TLO 激活所选刀具，无需对刀 — Ctrl+R</translation>
    </message>
    <message>
        <source>Machine busy</source>
        <translation>机床忙碌</translation>
    </message>
    <message>
        <source>Stop the machine</source>
        <translation>停止机床</translation>
    </message>
    <message>
        <source>Stop the machine now (Ctrl-X to the controller) — Esc</source>
        <translation>立即停止机床（向控制器发送 Ctrl-X）— Esc</translation>
    </message>
    <message>
        <source>Restore T%1 TLO</source>
        <translation>恢复 T%1 的 TLO</translation>
    </message>
    <message>
        <source>Nothing was written to the tool table.</source>
        <translation>刀具表中未写入任何内容。</translation>
    </message>
    <message>
        <source>Probe %1?</source>
        <translation>对 %1 对刀？</translation>
    </message>
    <message>
        <source>there is no tool in the spindle.</source>
        <translation>主轴上没有刀具。</translation>
    </message>
    <message>
        <source>Probing failed</source>
        <translation>对刀失败</translation>
    </message>
    <message>
        <source>Restore T%1?</source>
        <translation>恢复 T%1？</translation>
    </message>
    <message>
        <source>Restoring failed</source>
        <translation>恢复失败</translation>
    </message>
    <message>
        <source>T%1 measured: TLO %2, recorded in the table.</source>
        <translation>T%1 已测量：TLO %2，已记录到刀具表。</translation>
    </message>
    <message>
        <source>Measured TLO %1, but it could not be recorded: %2</source>
        <translation>测得 TLO %1，但无法记录：%2</translation>
    </message>
    <message>
        <source>Is T%1 in the spindle now?</source>
        <translation>T%1 现在在主轴上吗？</translation>
    </message>
    <message>
        <source>The machine will use T%1&apos;s TLO %2 (%3, %4) without probing. If another tool is in the spindle, the next cut is off by the difference.</source>
        <translation>机床将不经对刀直接使用 T%1 的 TLO %2（%3，%4）。如果主轴上是另一把刀具，下一次切削会偏差两者之差。</translation>
    </message>
    <message>
        <source>set by hand</source>
        <translation>手动设置</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>已测量</translation>
    </message>
    <message>
        <source>T%1 failed its last break test.</source>
        <translation>T%1 未通过上次断刀检测。</translation>
    </message>
    <message>
        <source>T%1 Is in the Spindle</source>
        <translation>T%1 在主轴上</translation>
    </message>
    <message>
        <source>T%1 is active with TLO %2.</source>
        <translation>T%1 已激活，TLO 为 %2。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO does not fit this machine&apos;s reference</source>
        <translation>T%1 的 TLO 与本机床的基准不符</translation>
    </message>
    <message>
        <source>The table does not say which reference tool T%1&apos;s TLO was measured against: make sure it is the reference the machine has now.</source>
        <translation>刀具表未记录 T%1 的 TLO 是相对于哪把基准刀具测得的：请确认它就是机床当前的基准。</translation>
    </message>
    <message>
        <source>The spindle is empty: load a tool first (Rack ▸ Load).</source>
        <translation>主轴为空：请先装入刀具（刀库 ▸ 装入）。</translation>
    </message>
    <message>
        <source>The machine will move: up to clearance, over the tool setter, then down until %1 touches it. Keep hands clear.

The machine says %1 is in the spindle: the measurement is recorded as %1&apos;s TLO.

Probe now?</source>
        <translation>机床将移动：升到安全高度，移到对刀仪上方，然后下降直到 %1 接触它。请勿将手靠近。

机床报告 %1 在主轴上：测量结果将记录为 %1 的 TLO。

现在对刀？</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was measured against a reference tool at MCS Z %3, but the machine&apos;s reference is now at MCS Z %4 (another machine&apos;s TLO, or the machine was calibrated again since). Restored, it would be off by %5.

Probe T%1 instead.</source>
        <translation>T%1 的 TLO %2 是相对 MCS Z %3 处的基准刀测量的，但机床当前基准位于 MCS Z %4（另一台机床的 TLO，或机床之后重新校准过）。若恢复，将偏差 %5。

请改为对 T%1 对刀。</translation>
    </message>
    <message>
        <source>The machine reports no reference tool MCS Z: a stored TLO is only right against the reference it was measured from.</source>
        <translation>机床未报告基准刀 MCS Z：已存 TLO 仅相对其测量时的基准才正确。</translation>
    </message>
    <message>
        <source>Sends: %1</source>
        <translation>发送：%1</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was set by hand, not measured on the tool setter.</source>
        <translation>T%1 的 TLO 是手动设置的，并非在对刀仪上测量。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO is dated in the future (%2): a clock was wrong, and when it was measured is not known.</source>
        <translation>T%1 的 TLO 日期在未来（%2）：某个时钟有误，无法知道其测量时间。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO is %2 days old, older than the stale limit (%3 d): the cutter may have worn or been changed since.</source>
        <translation>T%1 的 TLO 已有 %2 天，超过过期期限（%3 天）：刀具此后可能已磨损或被更换。</translation>
    </message>
    <message>
        <source>This machine has no reference tool yet: %1 becomes it (TLO 0.000), and every tool measured after it gets its length against %1&apos;s. Probe the tool you mean to keep as the reference.</source>
        <translation>这台机器还没有基准刀具：%1 将成为基准（TLO 0.000），之后测量的每把刀具都以 %1 为基准得到长度。请测量您打算保留为基准的刀具。</translation>
    </message>
    <message>
        <source>read from the controller</source>
        <translation>从控制器读取</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO was read from the controller&apos;s table, not measured on the tool setter.</source>
        <translation>T%1 的 TLO 是从控制器的刀具表读取的，并未在对刀仪上测量。</translation>
    </message>
    <message>
        <source>The machine says no tool is in the spindle (T0), so there is nothing to probe. Say which tool is in first (the table&apos;s context menu: Make Active).</source>
        <translation>机床报告主轴上没有刀具（T0），因此没有可探测的刀具。请先指明装的是哪把刀具（刀具表的右键菜单：设为当前刀具）。</translation>
    </message>
    <message>
        <source>Nothing to probe</source>
        <translation>没有可探测的刀具</translation>
    </message>
    <message>
        <source>As its settings say: %1.</source>
        <translation>按其设置：%1。</translation>
    </message>
</context>
<context>
    <name>Toffee::ProbePlan</name>
    <message>
        <source>%1 touches</source>
        <translation>%1 次触碰</translation>
    </message>
    <message>
        <source>X %1 Y %2 mm from the setter&apos;s centre</source>
        <translation>距对刀仪中心 X %1 Y %2 mm</translation>
    </message>
    <message>
        <source>latch at %1 mm/min</source>
        <translation>慢速进给 %1 mm/min</translation>
    </message>
</context>
<context>
    <name>Toffee::ProbeSettings</name>
    <message>
        <source>A touch-off point lies at most %1 %2 from the setter&apos;s centre in X and Y.</source>
        <translation>触碰点在 X 和 Y 方向距对刀仪中心最多 %1 %2。</translation>
    </message>
    <message>
        <source>A tool is touched 1 to %1 times.</source>
        <translation>刀具触碰 1 到 %1 次。</translation>
    </message>
    <message>
        <source>A latch feed must be more than 0 and at most %1 %2/min.</source>
        <translation>慢速进给必须大于 0 且不超过 %1 %2/min。</translation>
    </message>
    <message>
        <source>A spread limit must be more than 0 and at most %1 %2.</source>
        <translation>差值上限必须大于 0 且不超过 %1 %2。</translation>
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
        <translation>1 刃</translation>
    </message>
    <message>
        <source>%1 edges</source>
        <translation>%1 刃</translation>
    </message>
    <message>
        <source>1 touch</source>
        <translation>1 次触碰</translation>
    </message>
    <message>
        <source>%1 touches</source>
        <translation>%1 次触碰</translation>
    </message>
    <message>
        <source>same edge</source>
        <translation>同一刃</translation>
    </message>
    <message>
        <source>latch %1</source>
        <translation>慢速进给 %1</translation>
    </message>
    <message>
        <source>spread %1</source>
        <translation>差值 %1</translation>
    </message>
    <message>
        <source>Type how the tool is measured, any of: &quot;X 30&quot; and &quot;Y 0&quot; (the touch-off point from the setter&apos;s centre), &quot;4 edges&quot;, &quot;4 touches&quot;, &quot;same edge&quot; (no turn between touches), &quot;latch 20&quot; (the slow touch&apos;s feed per minute), &quot;spread 0.02&quot; (the widest spread that is no finding), separated by commas; empty for one touch at the centre.</source>
        <translation>输入刀具的测量方式，可任选：“X 30”和“Y 0”（触碰点距对刀仪中心的距离）、“4 刃”、“4 次触碰”、“同一刃”（触碰之间不转动）、“慢速进给 20”（慢速触碰每分钟的进给）、“差值 0.02”（不算异常的最大差值），用逗号分隔；留空则在中心触碰一次。</translation>
    </message>
    <message>
        <source>touches</source>
        <translation>次触碰</translation>
    </message>
    <message>
        <source>touch</source>
        <translation>次</translation>
    </message>
    <message>
        <source>edges</source>
        <translation>刃</translation>
    </message>
    <message>
        <source>edge</source>
        <translation>个刃</translation>
    </message>
    <message>
        <source>flutes</source>
        <translation>齿</translation>
    </message>
    <message>
        <source>latch</source>
        <translation>慢速进给</translation>
    </message>
    <message>
        <source>spread</source>
        <translation>差值</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a probing setting. %2</source>
        <translation>“%1”不是测量设置。%2</translation>
    </message>
    <message>
        <source>A cutter has 1 to %1 cutting edges.</source>
        <translation>刀具有 1 到 %1 个刃。</translation>
    </message>
</context>
<context>
    <name>Toffee::ProgramUse</name>
    <message>
        <source>%1 Nothing was recorded.</source>
        <translation>%1 未记录任何内容。</translation>
    </message>
</context>
<context>
    <name>Toffee::PtyServer</name>
    <message>
        <source>cannot open a pseudo-terminal: %1</source>
        <translation>无法打开伪终端：%1</translation>
    </message>
    <message>
        <source>cannot make the link %1</source>
        <translation>无法创建链接 %1</translation>
    </message>
</context>
<context>
    <name>Toffee::RackPanel</name>
    <message>
        <source>Measure Rack…</source>
        <translation>测量刀库…</translation>
    </message>
    <message>
        <source>Check Rack…</source>
        <translation>检查刀库…</translation>
    </message>
    <message>
        <source>After a manual change, use the tool&apos;s stored TLO
when it is fresh (no probe)</source>
        <translation>手动换刀后，如果刀具的已存 TLO 未过期，
则直接使用（不对刀）</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>The tool in the spindle</source>
        <translation>主轴中的刀具</translation>
    </message>
    <message>
        <source>The machine&apos;s firmware</source>
        <translation>机床的固件</translation>
    </message>
    <message>
        <source>The tools the rack holds</source>
        <translation>刀库中的刀具</translation>
    </message>
    <message>
        <source>Why the rack is not understood</source>
        <translation>无法识别刀库设置的原因</translation>
    </message>
    <message>
        <source>The rack&apos;s tools</source>
        <translation>刀库的刀具</translation>
    </message>
    <message>
        <source>The tool to load</source>
        <translation>要装入的刀具</translation>
    </message>
    <message>
        <source>Load the tool</source>
        <translation>装入刀具</translation>
    </message>
    <message>
        <source>Measure every rack tool</source>
        <translation>测量刀库中的每把刀具</translation>
    </message>
    <message>
        <source>Break-test every rack tool</source>
        <translation>对刀库中的每把刀具进行断刀检测</translation>
    </message>
    <message>
        <source>Rack check tolerance in millimetres</source>
        <translation>刀库检查公差（毫米）</translation>
    </message>
    <message>
        <source>Use a fresh stored TLO after a manual change</source>
        <translation>手动换刀后使用未过期的已存 TLO</translation>
    </message>
    <message>
        <source>Rack progress</source>
        <translation>刀库操作进度</translation>
    </message>
    <message>
        <source>What the machine does now</source>
        <translation>机床当前的动作</translation>
    </message>
    <message>
        <source>Cancel the rack operation</source>
        <translation>取消刀库操作</translation>
    </message>
    <message>
        <source>The last rack operation&apos;s result</source>
        <translation>上次刀库操作的结果</translation>
    </message>
    <message>
        <source>1-6 on a Carvera C1, or tool numbers and ranges (1,2,5-8); the job check uses the same rack.</source>
        <translation>Carvera C1 为 1-6，或刀具号及范围（1,2,5-8）；作业检查使用同一刀库。</translation>
    </message>
    <message>
        <source>1-6, or none</source>
        <translation>1-6 或 none</translation>
    </message>
    <message>
        <source>Any tool: one outside the rack is a manual change</source>
        <translation>任意刀具：不在刀库中的刀具需手动换刀</translation>
    </message>
    <message>
        <source>A rack tool is always measured by the machine at its change.</source>
        <translation>刀库中的刀具在换刀时总是由机床测量。</translation>
    </message>
    <message>
        <source>%v of %m</source>
        <translation>%v / %m</translation>
    </message>
    <message>
        <source>&amp;Rack holds:</source>
        <translation>刀库包含(&amp;R)：</translation>
    </message>
    <message>
        <source>Connect to the machine first.</source>
        <translation>请先连接机床。</translation>
    </message>
    <message>
        <source>Load T%1…</source>
        <translation>装入 T%1…</translation>
    </message>
    <message>
        <source>Break-test every rack tool against its stored TLO; the machine halts on a broken one.</source>
        <translation>将刀库中的每把刀具与其已存 TLO 比较，进行断刀检测；遇到断刀时机床会停机。</translation>
    </message>
    <message>
        <source>Change to every rack tool in turn and measure it on the tool setter.</source>
        <translation>依次换到刀库中的每把刀具，并在对刀仪上测量。</translation>
    </message>
    <message>
        <source>Change to the tool: the machine puts the one in the spindle back first.</source>
        <translation>换到该刀具：机床会先放回主轴中的刀具。</translation>
    </message>
    <message>
        <source>Spindle: unknown</source>
        <translation>主轴：未知</translation>
    </message>
    <message>
        <source>Spindle: empty</source>
        <translation>主轴：空</translation>
    </message>
    <message>
        <source>Spindle: T%1</source>
        <translation>主轴：T%1</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>%1 — no break test</source>
        <translation>%1 — 无断刀检测</translation>
    </message>
    <message>
        <source>T%1 is in the spindle already: the machine measures it again on the tool setter.</source>
        <translation>T%1 已在主轴上：机床会在对刀仪上重新测量它。</translation>
    </message>
    <message>
        <source>The machine puts T%1 back in the rack, picks T%2 and measures it on the tool setter.</source>
        <translation>机床将 T%1 放回刀库，取出 T%2 并在对刀仪上测量。</translation>
    </message>
    <message>
        <source>The machine puts T%1 back in the rack.</source>
        <translation>机床将 T%1 放回刀库。</translation>
    </message>
    <message>
        <source>T%1 has no slot in the rack: take it out of the spindle when the machine asks.</source>
        <translation>T%1 在刀库中没有刀位：机床提示时请将其从主轴上取下。</translation>
    </message>
    <message>
        <source>The machine picks T%1 from the rack and measures it on the tool setter.</source>
        <translation>机床从刀库取出 T%1 并在对刀仪上测量。</translation>
    </message>
    <message>
        <source>T%1 has no slot in the rack: put it in the spindle when the machine asks. The machine then takes its stored TLO %2 (measured %3) and does not probe it.</source>
        <translation>T%1 在刀库中没有刀位：机床提示时请将其装入主轴。机床随后采用其已存 TLO %2（测量于 %3），不对其对刀。</translation>
    </message>
    <message>
        <source>T%1 has no slot in the rack: put it in the spindle when the machine asks. The machine then measures it on the tool setter.</source>
        <translation>T%1 在刀库中没有刀位：机床提示时请将其装入主轴。机床随后在对刀仪上测量它。</translation>
    </message>
    <message>
        <source>The stored TLO is not used: %1</source>
        <translation>不使用已存 TLO：%1</translation>
    </message>
    <message>
        <source>Keep clear of the machine.</source>
        <translation>请远离机床。</translation>
    </message>
    <message>
        <source>Load T%1?</source>
        <translation>装入 T%1？</translation>
    </message>
    <message>
        <source>Loading T%1 failed</source>
        <translation>装入 T%1 失败</translation>
    </message>
    <message>
        <source>Nothing was written to the tool table.</source>
        <translation>刀具表中未写入任何内容。</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>未知</translation>
    </message>
    <message>
        <source>T%1 is in the spindle with TLO %2, but it could not be recorded: %3</source>
        <translation>T%1 已在主轴上，TLO 为 %2，但无法记录：%3</translation>
    </message>
    <message>
        <source>T%1 takes its stored TLO %2 (measured %3); not probed.</source>
        <translation>T%1 采用其已存 TLO %2（测量于 %3）；未对刀。</translation>
    </message>
    <message>
        <source>T%1 measured: TLO %2, recorded in the table.</source>
        <translation>T%1 已测量：TLO %2，已记录到刀具表。</translation>
    </message>
    <message>
        <source>Stopping after this tool…</source>
        <translation>将在此刀具后停止…</translation>
    </message>
    <message>
        <source>Stop the machine?</source>
        <translation>停止机床？</translation>
    </message>
    <message>
        <source>Stop the machine now? It halts; Unlock afterwards.</source>
        <translation>立即停止机床？机床将停机；之后请解锁。</translation>
    </message>
    <message>
        <source>Check the rack?</source>
        <translation>检查刀库？</translation>
    </message>
    <message>
        <source>Measure the rack?</source>
        <translation>测量刀库？</translation>
    </message>
    <message>
        <source>The machine changes to %1 in turn and break-tests each against its stored TLO (tolerance %2). A broken tool halts the machine and stops the check. After the last, T%3 goes back in the rack.</source>
        <translation>机床将依次换到 %1，并将每把刀具与其已存 TLO 比较，进行断刀检测（公差 %2）。遇到断刀时机床会停机并终止检查。最后一把完成后，T%3 会放回刀库。</translation>
    </message>
    <message>
        <source>The machine changes to %1 in turn, putting the tool in the spindle back in the rack first, and measures each on the tool setter; each TLO is recorded in the table. T%2 stays in the spindle.</source>
        <translation>机床将依次换到 %1（先将主轴中的刀具放回刀库），并在对刀仪上逐一测量；每个 TLO 都会记录到刀具表中。T%2 将留在主轴上。</translation>
    </message>
    <message>
        <source>T%1: %2</source>
        <translation>T%1：%2</translation>
    </message>
    <message>
        <source>Not run: %1.</source>
        <translation>未执行：%1。</translation>
    </message>
    <message>
        <source>A measurement could not be stored in the table, so the rack was stopped: %1</source>
        <translation>有一次测量无法保存到刀具表中，因此刀库操作已停止：%1</translation>
    </message>
    <message>
        <source>The rack was stopped</source>
        <translation>刀库操作已停止</translation>
    </message>
    <message>
        <source>The rack check failed</source>
        <translation>刀库检查失败</translation>
    </message>
    <message>
        <source>Measuring the rack failed</source>
        <translation>测量刀库失败</translation>
    </message>
    <message>
        <source>Rack checked: 1 tool passed.</source>
        <translation>刀库已检查：1 把刀具通过。</translation>
    </message>
    <message>
        <source>Rack checked: %1 tools passed.</source>
        <translation>刀库已检查：%1 把刀具通过。</translation>
    </message>
    <message>
        <source>Rack measured: 1 tool, its TLO recorded in the table.</source>
        <translation>刀库已测量：1 把刀具，其 TLO 已记录到刀具表。</translation>
    </message>
    <message>
        <source>Rack measured: %1 tools, each TLO recorded in the table.</source>
        <translation>刀库已测量：%1 把刀具，每个 TLO 都已记录到刀具表。</translation>
    </message>
    <message>
        <source>The tool</source>
        <translation>该刀具</translation>
    </message>
    <message>
        <source>%1 may be broken: the check stopped and the machine halted.</source>
        <translation>%1 可能已断：检查已停止，机床已停机。</translation>
    </message>
    <message>
        <source>%1 may be broken</source>
        <translation>%1 可能已断</translation>
    </message>
    <message>
        <source>%1 may be broken. The rack check stopped there, and the machine has halted.</source>
        <translation>%1 可能已断。刀库检查在此停止，机床已停机。</translation>
    </message>
    <message>
        <source>The table marks %1 until it is measured again: once it is checked or replaced and the machine unlocked (the strip&apos;s Unlock, Ctrl+Shift+U), measure it with Load Tool or Measure Rack.</source>
        <translation>刀具表会一直标记 %1，直到重新测量：检查或更换刀具并解锁机床（状态栏的“解锁”，Ctrl+Shift+U）后，请用“装入”或“测量刀库”测量它。</translation>
    </message>
    <message>
        <source>Slot</source>
        <translation>刀位</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>刀具</translation>
    </message>
    <message>
        <source>Stored TLO</source>
        <translation>已存 TLO</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>测量时间</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>In millimetres</source>
        <translation>单位：毫米</translation>
    </message>
    <message>
        <source>This session&apos;s Measure Rack or Check Rack, with the TLO measured (mm)</source>
        <translation>本次会话中“测量刀库”或“检查刀库”的结果，附测得的 TLO（mm）</translation>
    </message>
    <message>
        <source>never</source>
        <translation>从未</translation>
    </message>
    <message>
        <source>failed break test</source>
        <translation>断刀检测未通过</translation>
    </message>
    <message>
        <source>set by hand</source>
        <translation>手动设置</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>已测量</translation>
    </message>
    <message>
        <source>T%1 · in spindle</source>
        <translation>T%1 · 在主轴上</translation>
    </message>
    <message>
        <source>Not in the table</source>
        <translation>不在刀具表中</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <source>Checking…</source>
        <translation>正在检查…</translation>
    </message>
    <message>
        <source>Measuring…</source>
        <translation>正在测量…</translation>
    </message>
    <message>
        <source>Measured: %1</source>
        <translation>已测量：%1</translation>
    </message>
    <message>
        <source>Passed</source>
        <translation>通过</translation>
    </message>
    <message>
        <source>Passed: %1</source>
        <translation>通过：%1</translation>
    </message>
    <message>
        <source>BROKEN</source>
        <translation>断刀</translation>
    </message>
    <message>
        <source>BROKEN: %1</source>
        <translation>断刀：%1</translation>
    </message>
    <message>
        <source>Failed</source>
        <translation>失败</translation>
    </message>
    <message>
        <source>Not run</source>
        <translation>未执行</translation>
    </message>
    <message>
        <source>Empty</source>
        <translation>空</translation>
    </message>
    <message>
        <source>Empty the Spindle…</source>
        <translation>清空主轴…</translation>
    </message>
    <message>
        <source>The machine puts T%1 back in the rack; the spindle stays empty.</source>
        <translation>机床将 T%1 放回刀库；主轴保持为空。</translation>
    </message>
    <message>
        <source>Take the tool out of the spindle when the machine asks; the spindle stays empty.</source>
        <translation>机床提示时，从主轴上取下刀具；主轴保持为空。</translation>
    </message>
    <message>
        <source>Empty the spindle?</source>
        <translation>清空主轴？</translation>
    </message>
    <message>
        <source>The spindle is empty.</source>
        <translation>主轴已空。</translation>
    </message>
    <message>
        <source>The machine stopped during T%1&apos;s step: look which tool is in the spindle and that the rack holds the others before you Unlock, then measure the tool in the spindle.</source>
        <translation>机床在 T%1 的步骤中停止：解锁前请目视检查主轴上是哪把刀、刀库是否装有其余刀具，然后对主轴上的刀具对刀。</translation>
    </message>
    <message>
        <source>Skipped</source>
        <translation>已跳过</translation>
    </message>
    <message>
        <source>%1 has no tool rack: the rack is the Carvera&apos;s.</source>
        <translation>%1 没有刀库：刀库是 Carvera 的功能。</translation>
    </message>
    <message>
        <source>read from the controller</source>
        <translation>从控制器读取</translation>
    </message>
</context>
<context>
    <name>Toffee::RackSequence</name>
    <message>
        <source>The rack holds no tools: say which tools it holds (1-6 on a C1) first.</source>
        <translation>刀库中没有刀具：请先说明刀库中有哪些刀具（C1 为 1-6）。</translation>
    </message>
    <message>
        <source>The machine runs %1, whose M491.1 only measures a tool again without comparing: a rack check there would pass a broken tool. Install the community firmware to check the rack.</source>
        <translation>机床运行的是 %1，其 M491.1 只会重新测量刀具而不作比较：在此进行刀库检查会让断刀通过。请安装社区固件以检查刀库。</translation>
    </message>
    <message>
        <source>The machine did not say which firmware it runs, so Toffee cannot tell whether its M491.1 compares a tool with its TLO. The rack was not checked.</source>
        <translation>机床未说明其运行的固件，因此 Toffee 无法判断其 M491.1 是否将刀具与其 TLO 比较。未检查刀库。</translation>
    </message>
    <message>
        <source>%1 have no stored TLO to compare with. Measure them first (Measure Rack); nothing moved.</source>
        <translation>%1 没有可供比较的已存 TLO。请先测量它们（测量刀库）；机床未移动。</translation>
    </message>
    <message>
        <source>Measuring the rack…</source>
        <translation>正在测量刀库…</translation>
    </message>
    <message>
        <source>Checking the rack…</source>
        <translation>正在检查刀库…</translation>
    </message>
    <message>
        <source>The machine is busy or not connected.</source>
        <translation>机床正忙或未连接。</translation>
    </message>
    <message>
        <source>Measuring T%1 (%2 of %3)…</source>
        <translation>正在测量 T%1（第 %2 把，共 %3 把）…</translation>
    </message>
    <message>
        <source>Checking T%1 (%2 of %3)…</source>
        <translation>正在检查 T%1（第 %2 把，共 %3 把）…</translation>
    </message>
    <message>
        <source>The connection to the machine was closed; the rack was not finished.</source>
        <translation>与机床的连接已关闭；刀库操作未完成。</translation>
    </message>
    <message>
        <source>Cancelled after the last tool: every tool was done, and T%1 stays in the spindle.</source>
        <translation>在最后一把刀具后取消：所有刀具均已完成，T%1 留在主轴上。</translation>
    </message>
    <message>
        <source>Cancelled: the rack was stopped after T%1, which is in the spindle.</source>
        <translation>已取消：刀库操作在 T%1 之后停止，T%1 在主轴上。</translation>
    </message>
    <message>
        <source>Putting T%1 back in the rack…</source>
        <translation>正在将 T%1 放回刀库…</translation>
    </message>
    <message>
        <source>Every tool passed, but the last one could not be put back: %1</source>
        <translation>所有刀具均已通过，但最后一把无法放回：%1</translation>
    </message>
    <message>
        <source>T%1&apos;s stored TLO was measured against reference MCS Z %2, but the machine&apos;s reference is at %3 now, %4 away: every comparison would be off by that much. Check the machine&apos;s calibration and the tool setter; if they are sound, measure the rack again (Measure Rack).</source>
        <translation>T%1 的已存 TLO 是相对基准 MCS Z %2 测量的，但机床当前基准位于 %3，相差 %4：每次比较都会偏差这么多。请检查机床的校准和对刀仪；若两者完好，请重新测量刀库（测量刀库）。</translation>
    </message>
</context>
<context>
    <name>Toffee::RemoveToolsCommand</name>
    <message>
        <source>Remove tool T%1</source>
        <translation>删除刀具 T%1</translation>
    </message>
    <message>
        <source>Remove %1 tools</source>
        <translation>删除 %1 把刀具</translation>
    </message>
</context>
<context>
    <name>Toffee::RowReader</name>
    <message>
        <source>a blob of %1 bytes</source>
        <translation>%1 字节的二进制数据</translation>
    </message>
    <message>
        <source>a row&apos;s tool number is %1, not a tool number (%2 to %3)</source>
        <translation>某行的刀具号为 %1，不是刀具号（%2 到 %3）</translation>
    </message>
    <message>
        <source>T%1&apos;s row</source>
        <translation>T%1 的行</translation>
    </message>
    <message>
        <source>its version is %1, not a whole number from 1 up</source>
        <translation>其版本为 %1，不是从 1 起的整数</translation>
    </message>
    <message>
        <source>&quot;deleted&quot; is %1, not 0 or 1</source>
        <translation>“deleted”为 %1，不是 0 或 1</translation>
    </message>
    <message>
        <source>its data is %1 characters long; no tool&apos;s is longer than %2 KB</source>
        <translation>其数据长 %1 个字符；任何刀具的数据都不超过 %2 KB</translation>
    </message>
    <message>
        <source>its data is %1, not a tool</source>
        <translation>其数据为 %1，不是刀具</translation>
    </message>
    <message>
        <source>its data is T%1&apos;s, not T%2&apos;s</source>
        <translation>其数据属于 T%1，而不是 T%2</translation>
    </message>
    <message>
        <source>event %1: %2</source>
        <translation>事件 %1：%2</translation>
    </message>
    <message>
        <source>its id is not an event&apos;s</source>
        <translation>其标识不是事件的标识</translation>
    </message>
    <message>
        <source>it names no machine</source>
        <translation>未指明机器</translation>
    </message>
    <message>
        <source>its tool %1 is not a tool number</source>
        <translation>其刀具 %1 不是刀具号</translation>
    </message>
    <message>
        <source>it has no valid time</source>
        <translation>没有有效时间</translation>
    </message>
    <message>
        <source>its %1 is %2, which no machine measures</source>
        <translation>其 %1 为 %2，没有机器会测得此值</translation>
    </message>
    <message>
        <source>its tolerance is negative</source>
        <translation>其公差为负</translation>
    </message>
    <message>
        <source>an event&apos;s row has %1 columns, not %2</source>
        <translation>事件行有 %1 列，而不是 %2 列</translation>
    </message>
    <message>
        <source>its id is not text of up to %1 characters</source>
        <translation>其标识不是最多 %1 个字符的文本</translation>
    </message>
    <message>
        <source>its machine is %1, not a machine&apos;s name</source>
        <translation>其机器为 %1，不是机器名称</translation>
    </message>
    <message>
        <source>its tool is %1, not a tool number (%2 to %3)</source>
        <translation>其刀具为 %1，不是刀具号（%2 到 %3）</translation>
    </message>
    <message>
        <source>its time is %1, not a time in UTC (2026-11-23T08:10:00.125Z)</source>
        <translation>其时间为 %1，不是 UTC 时间（2026-11-23T08:10:00.125Z）</translation>
    </message>
    <message>
        <source>its kind is %1, not one Toffee records</source>
        <translation>其类型为 %1，不是 Toffee 记录的类型</translation>
    </message>
    <message>
        <source>its %1 is %2, not a number</source>
        <translation>其 %1 为 %2，不是数字</translation>
    </message>
    <message>
        <source>&quot;failed&quot; is %1, not 0 or 1</source>
        <translation>“failed”为 %1，不是 0 或 1</translation>
    </message>
    <message>
        <source>a tool use&apos;s row has %1 columns, not 7</source>
        <translation>刀具使用行有 %1 列，而不是 7 列</translation>
    </message>
    <message>
        <source>tool use %1: %2</source>
        <translation>刀具使用 %1：%2</translation>
    </message>
    <message>
        <source>its tool is %1, not a tool number</source>
        <translation>其刀具为 %1，不是刀具号</translation>
    </message>
    <message>
        <source>its time is %1, not a time in UTC</source>
        <translation>其时间为 %1，不是 UTC 时间</translation>
    </message>
    <message>
        <source>its program is %1, not a file name</source>
        <translation>其程序为 %1，不是文件名</translation>
    </message>
    <message>
        <source>its cutting time is %1, not a number of seconds</source>
        <translation>其切削时间为 %1，不是秒数</translation>
    </message>
    <message>
        <source>its feed path is %1, not a length</source>
        <translation>其进给路径为 %1，不是长度</translation>
    </message>
    <message>
        <source>its touches are not 2 to %1 machine positions</source>
        <translation>其触碰不是 2 到 %1 个机床位置</translation>
    </message>
    <message>
        <source>its touches are %1, not machine positions</source>
        <translation>其触碰为 %1，不是机床位置</translation>
    </message>
</context>
<context>
    <name>Toffee::SelfTest</name>
    <message>
        <source>no progress within 20 s</source>
        <translation>20 秒内没有进展</translation>
    </message>
    <message>
        <source>self-test failed while %1: %2</source>
        <translation>自检在“%1”时失败：%2</translation>
    </message>
    <message>
        <source>showing the window</source>
        <translation>显示窗口</translation>
    </message>
    <message>
        <source>the window did not render</source>
        <translation>窗口没有绘制</translation>
    </message>
    <message>
        <source>loading the example table</source>
        <translation>加载示例表</translation>
    </message>
    <message>
        <source>the example table did not load</source>
        <translation>示例表未能加载</translation>
    </message>
    <message>
        <source>connecting to the built-in emulator</source>
        <translation>连接到内置模拟器</translation>
    </message>
    <message>
        <source>probing the current tool</source>
        <translation>对当前刀具对刀</translation>
    </message>
    <message>
        <source>the measurement did not reach the table</source>
        <translation>测量结果没有写入表中</translation>
    </message>
    <message>
        <source>rendering</source>
        <translation>绘制</translation>
    </message>
    <message>
        <source>self-test passed: first frame after %1 ms; T%2 probed, TLO %3 mm recorded</source>
        <translation>自检通过：%1 毫秒后显示第一帧；T%2 已对刀，TLO %3 mm 已记录</translation>
    </message>
</context>
<context>
    <name>Toffee::SerialPortTransport</name>
    <message>
        <source>Cannot open %1: %2. Check the cable, that no other program has the port open, and that you may use serial ports (the dialout group).</source>
        <translation>无法打开 %1：%2。请检查线缆、是否有其他程序占用该端口，以及您是否有使用串口的权限（dialout 组）。</translation>
    </message>
    <message>
        <source>%1 at %2 baud</source>
        <translation>%1，%2 波特</translation>
    </message>
    <message>
        <source>The port %1 stopped answering and was closed: the cable was unplugged, the machine switched off, or the program serving the port ended. Check the cable and the machine, then connect again.</source>
        <translation>端口 %1 停止响应并已关闭：电缆被拔出、机器已关闭，或为该端口服务的程序已结束。请检查电缆和机器，然后重新连接。</translation>
    </message>
    <message>
        <source>The port %1 failed (%2); the link was closed. Check the cable and connect again.</source>
        <translation>端口 %1 出错（%2）；连接已关闭。请检查线缆后重新连接。</translation>
    </message>
</context>
<context>
    <name>Toffee::SetterCycle</name>
    <message>
        <source>The tool&apos;s latch feed (%1 mm/min) must not be faster than the setter&apos;s search feed (%2 mm/min).</source>
        <translation>刀具的慢速进给（%1 mm/min）不得快于对刀仪的搜索进给（%2 mm/min）。</translation>
    </message>
    <message>
        <source>The tool&apos;s touch-off point (X %1, Y %2 mm) lies beyond the machine&apos;s coordinates.</source>
        <translation>刀具的触碰点（X %1、Y %2 mm）超出机床坐标范围。</translation>
    </message>
    <message>
        <source>%1 cannot turn its spindle to an angle, so the %2 touches met the setter wherever the spindle stood: their spread is the setter&apos;s repeatability and the cutter&apos;s runout there, not each edge&apos;s.</source>
        <translation>%1 无法将主轴转到指定角度，因此 %2 次触碰都在主轴停留的位置碰到对刀仪：其差值是对刀仪的重复精度和刀具在该处的跳动，而不是各刃的差值。</translation>
    </message>
</context>
<context>
    <name>Toffee::Spool</name>
    <message>
        <source>The folder %1 cannot be made, so nothing can be kept there.</source>
        <translation>无法创建文件夹 %1，因此无法在其中保存任何内容。</translation>
    </message>
    <message>
        <source>%1 was written to the library but cannot be removed from this computer; it will be sent again, and the library will find it already there.</source>
        <translation>%1 已写入库，但无法从此计算机删除；它将被再次发送，库会发现它已存在。</translation>
    </message>
    <message>
        <source>%1 is not a measurement Toffee kept: it was changed or damaged.</source>
        <translation>%1 不是 Toffee 保存的测量：它已被更改或损坏。</translation>
    </message>
    <message>
        <source>There is nothing to keep.</source>
        <translation>没有需要保存的内容。</translation>
    </message>
    <message>
        <source>It was moved to %1.</source>
        <translation>已移至 %1。</translation>
    </message>
    <message>
        <source>%1 event(s) of %2 cannot go into the history (%3). They were moved to %4 apart; the file&apos;s other events are sent.</source>
        <translation>%2 中有 %1 个事件无法写入历史（%3）。它们已单独移至 %4；该文件的其他事件已发送。</translation>
    </message>
</context>
<context>
    <name>Toffee::StreamTransport</name>
    <message>
        <source> (framed)</source>
        <translation>（帧协议）</translation>
    </message>
    <message>
        <source>%1 sent a line longer than %2 bytes; only its first %2 bytes were kept.</source>
        <translation>%1 发送了一行超过 %2 字节的内容；只保留了前 %2 字节。</translation>
    </message>
    <message>
        <source>%1 is not open.</source>
        <translation>%1 未打开。</translation>
    </message>
    <message>
        <source>%1 speaks Makera&apos;s frames (its firmware from 1.0.4 on), not the plain text chosen. Plain text would leave it deaf until it is restarted, so nothing more was sent. Choose automatic (--protocol auto, or leave it out) or framed.</source>
        <translation>%1 使用 Makera 的帧协议（其固件 1.0.4 起），而不是所选的纯文本。纯文本会使它在重启前不再响应，因此未再发送任何内容。请选择自动（--protocol auto，或省略）或帧协议（framed）。</translation>
    </message>
    <message>
        <source>%1 speaks plain text, not Makera&apos;s frames as chosen. Nothing more was sent. Choose automatic (--protocol auto, or leave it out) or text.</source>
        <translation>%1 使用纯文本，而不是所选的 Makera 帧协议。未再发送任何内容。请选择自动（--protocol auto，或省略）或纯文本（text）。</translation>
    </message>
    <message>
        <source>%1 did not answer within %2 s, in plain text or in Makera&apos;s frames. Check that the machine is switched on and has started, and the address or port.</source>
        <translation>%1 未在 %2 秒内以纯文本或 Makera 帧协议回答。请检查机器是否已开机并完成启动，以及地址或端口。</translation>
    </message>
</context>
<context>
    <name>Toffee::TableReading</name>
    <message>
        <source>tool %1 is already on line %2; tool numbers must be unique.</source>
        <translation>刀具 %1 已在第 %2 行；刀具号必须唯一。</translation>
    </message>
</context>
<context>
    <name>Toffee::TcpTransport</name>
    <message>
        <source>&quot;%1&quot; is not a machine&apos;s address: give HOST or HOST:PORT (the port is %2 when not given), such as 192.168.1.57 or carvera.local:2222.</source>
        <translation>“%1”不是机器地址：请输入 HOST 或 HOST:PORT（未给出端口时为 %2），例如 192.168.1.57 或 carvera.local:2222。</translation>
    </message>
    <message>
        <source>%1 over the network</source>
        <translation>通过网络连接 %1</translation>
    </message>
    <message>
        <source>%1 did not answer within %2 s. Check that the machine is switched on and on this network, and its address (the machine&apos;s screen shows it).</source>
        <translation>%1 在 %2 秒内没有应答。请检查机器是否已开机并在此网络中，以及它的地址（机器屏幕上有显示）。</translation>
    </message>
    <message>
        <source>Nothing answers at %1 (the connection was refused): the machine&apos;s Wi-Fi console is off, or the port is wrong (a Carvera listens on %2). Check the address and try again.</source>
        <translation>%1 无应答（连接被拒绝）：机器的 Wi-Fi 控制台已关闭，或端口错误（Carvera 监听 %2）。请检查地址后重试。</translation>
    </message>
    <message>
        <source>%1 is not a host name this computer can find. Give the machine&apos;s address as the machine&apos;s screen shows it (such as 192.168.1.57).</source>
        <translation>此计算机找不到主机名 %1。请按机器屏幕显示的地址输入（例如 192.168.1.57）。</translation>
    </message>
    <message>
        <source>Cannot reach %1: %2. Check that this computer and the machine are on the same network.</source>
        <translation>无法连接 %1：%2。请检查此计算机与机器是否在同一网络中。</translation>
    </message>
    <message>
        <source>The machine at %1 closed the connection: it was switched off or restarted, or it serves another program now. Check the machine, then connect again.</source>
        <translation>%1 处的机器关闭了连接：它已关机或重启，或正在服务另一个程序。请检查机器后重新连接。</translation>
    </message>
    <message>
        <source>The link to %1 was lost (%2): the machine was switched off or left the network. Check the machine, then connect again.</source>
        <translation>与 %1 的连接已断开（%2）：机器已关机或离开了网络。请检查机器后重新连接。</translation>
    </message>
</context>
<context>
    <name>Toffee::TloPanel</name>
    <message>
        <source>Machine state</source>
        <translation>机床状态</translation>
    </message>
    <message>
        <source>Active tool</source>
        <translation>当前刀具</translation>
    </message>
    <message>
        <source>Reference tool MCS Z</source>
        <translation>基准刀具机床坐标 Z</translation>
    </message>
    <message>
        <source>Current tool MCS Z</source>
        <translation>当前刀具机床坐标 Z</translation>
    </message>
    <message>
        <source>Tool length offset</source>
        <translation>刀具长度补偿</translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation>解锁</translation>
    </message>
    <message>
        <source>Unlock the machine</source>
        <translation>解锁机床</translation>
    </message>
    <message>
        <source>Clear the halt ($X) — Ctrl+Shift+U</source>
        <translation>解除停机（$X）— Ctrl+Shift+U</translation>
    </message>
    <message>
        <source>State:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <source>TLO:</source>
        <translation>TLO：</translation>
    </message>
    <message>
        <source>Connecting…</source>
        <translation>正在连接…</translation>
    </message>
    <message>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <source>Unlock failed</source>
        <translation>解锁失败</translation>
    </message>
    <message>
        <source>Where the tool length offset came from</source>
        <translation>刀具长度补偿的来源</translation>
    </message>
    <message>
        <source>Why the machine halted and what to do</source>
        <translation>机床停机的原因及处理方法</translation>
    </message>
    <message>
        <source>Tool:</source>
        <translation>刀具：</translation>
    </message>
    <message>
        <source>Reference Z:</source>
        <translation>基准 Z：</translation>
    </message>
    <message>
        <source>Current Z:</source>
        <translation>当前 Z：</translation>
    </message>
    <message>
        <source>HALTED</source>
        <translation>已停机</translation>
    </message>
    <message>
        <source>Connected</source>
        <translation>已连接</translation>
    </message>
    <message>
        <source>Nothing that moves the machine or changes its offsets runs until then.</source>
        <translation>在此之前，任何会移动机床或更改其补偿的操作都不会执行。</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>未测量</translation>
    </message>
    <message>
        <source>T%1 has no TLO in the table</source>
        <translation>T%1 在刀具表中没有 TLO</translation>
    </message>
    <message>
        <source>not T%1&apos;s: the table holds %2</source>
        <translation>不是 T%1 的：刀具表中为 %2</translation>
    </message>
    <message>
        <source>set by hand %1, not measured</source>
        <translation>于 %1 手动设置，未测量</translation>
    </message>
    <message>
        <source>measured %1</source>
        <translation>于 %1 测量</translation>
    </message>
    <message>
        <source>T%1 FAILED ITS BREAK TEST — %2</source>
        <translation>T%1 未通过断刀检测 — %2</translation>
    </message>
    <message>
        <source>The machine is still halted: check it, then try Unlock again.</source>
        <translation>机床仍处于停机状态：请检查机床，然后再次尝试解锁。</translation>
    </message>
    <message>
        <source>Idle</source>
        <translation>空闲</translation>
    </message>
    <message>
        <source>Running</source>
        <translation>运行中</translation>
    </message>
    <message>
        <source>Held</source>
        <translation>暂停保持</translation>
    </message>
    <message>
        <source>Alarm</source>
        <translation>报警</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>回零中</translation>
    </message>
    <message>
        <source>Asleep</source>
        <translation>休眠</translation>
    </message>
    <message>
        <source>Paused</source>
        <translation>已暂停</translation>
    </message>
    <message>
        <source>Waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <source>The machine reported an alarm.</source>
        <translation>机床报告了报警。</translation>
    </message>
    <message>
        <source>Check the machine, then Unlock ($X).</source>
        <translation>检查机床，然后解锁（$X）。</translation>
    </message>
    <message>
        <source>not reported</source>
        <translation>未报告</translation>
    </message>
    <message>
        <source>the machine has no TLO in force: probe the tool first</source>
        <translation>机床没有生效的 TLO：请先对刀</translation>
    </message>
    <message>
        <source>The break test found %1 broken, and the machine halted with the length it measured in force (%2 above).
Check the tool, then Unlock: Toffee sets its stored TLO, %3, back first.</source>
        <translation>断刀检测发现 %1 已断，机床已停机，测得的长度正在生效（上方的 %2）。
请检查刀具，然后解锁：Toffee 会先恢复其已存 TLO %3。</translation>
    </message>
    <message>
        <source>the tool</source>
        <translation>该刀具</translation>
    </message>
    <message>
        <source>its TLO</source>
        <translation>其 TLO</translation>
    </message>
    <message>
        <source>Unlock with T%1 marked broken?</source>
        <translation>在 T%1 被标记为断刀时解锁？</translation>
    </message>
    <message>
        <source>T%1 failed its break test: it may be broken, and the machine halted so that it cuts nothing more.</source>
        <translation>T%1 未通过断刀检测：它可能已断，机器已停机，以免它继续切削。</translation>
    </message>
    <message>
        <source>Look at the tool first, and replace it if it is broken. Unlock sets T%1&apos;s stored TLO, %2, back before anything can move; the mark stays until T%1 is measured again (Probe).</source>
        <translation>请先查看刀具，如已断请更换。解锁会在任何运动之前恢复 T%1 的已存刀长补偿 %2；标记会保留，直到重新测量 T%1（测量）。</translation>
    </message>
    <message>
        <source>Look at the tool first, and replace it if it is broken. The mark stays until T%1 is measured again (Probe).</source>
        <translation>请先查看刀具，如已断请更换。标记会保留，直到重新测量 T%1（测量）。</translation>
    </message>
    <message>
        <source>no status report yet</source>
        <translation>尚无状态报告</translation>
    </message>
    <message>
        <source>no status report for %1 s</source>
        <translation>已 %1 秒无状态报告</translation>
    </message>
    <message>
        <source>HALTED (%1; it stays halted until unlocked)</source>
        <translation>已停机（%1；解锁前保持停机）</translation>
    </message>
    <message>
        <source>%1 (stale: %2)</source>
        <translation>%1（已过时：%2）</translation>
    </message>
    <message>
        <source>Waiting for the operator</source>
        <translation>等待操作员</translation>
    </message>
    <message>
        <source>The machine said: “%1”</source>
        <translation>机器报告：“%1”</translation>
    </message>
    <message>
        <source>Look at the tool first, and replace it if it is broken. Unlock sets T%1&apos;s stored TLO, %2, back before anything can move: it was set by hand, not measured, and the break test measured %3. Probe T%1 before it cuts; the mark stays until then.</source>
        <translation>请先检查刀具，如已断裂请更换。解锁会在任何运动之前恢复 T%1 存储的 TLO %2：该值是手动设置的，并非测量所得，而断刀检测测得 %3。切削前请测量 T%1；在此之前标记保留。</translation>
    </message>
    <message>
        <source>another length</source>
        <translation>另一个长度</translation>
    </message>
    <message>
        <source>&amp;Unlock</source>
        <comment>the strip&apos;s button</comment>
        <translation>解锁(&amp;U)</translation>
    </message>
    <message>
        <source>as the table&apos;s, measured %1</source>
        <translation>与表中相同，测量于 %1</translation>
    </message>
    <message>
        <source>read from the controller %1, not measured</source>
        <translation>%1 从控制器读取，未测量</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolChangeWait</name>
    <message>
        <source>Put T%1 in the Spindle</source>
        <translation>将 T%1 装入主轴</translation>
    </message>
    <message>
        <source>The machine waits for T%1. Put it in the spindle, then press cycle start on the machine or Continue here; it is then measured.</source>
        <translation>机器正在等待 T%1。请将其装入主轴，然后按机器上的循环启动或此处的“继续”；随后将测量该刀具。</translation>
    </message>
    <message>
        <source>The machine waits for T%1. Put it in the spindle, then press the machine&apos;s button; it is then measured.</source>
        <translation>机器正在等待 T%1。请将其装入主轴，然后按机器上的按钮；随后将测量该刀具。</translation>
    </message>
    <message>
        <source>The change waits up to %1 min; End the Change stops it on the machine and records nothing.</source>
        <translation>换刀最多等待 %1 分钟；“结束换刀”会在机器上停止换刀，且不记录任何内容。</translation>
    </message>
    <message>
        <source>Continue</source>
        <translation>继续</translation>
    </message>
    <message>
        <source>End the Change</source>
        <translation>结束换刀</translation>
    </message>
    <message>
        <source>The operator ended the change in the window.</source>
        <translation>操作员在窗口中结束了换刀。</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolContextMenu</name>
    <message>
        <source>Make &amp;Active (No Probe)…</source>
        <translation>设为当前刀具（不测量）(&amp;A)…</translation>
    </message>
    <message>
        <source>&amp;Set Its TLO…</source>
        <translation>设置其 TLO(&amp;S)…</translation>
    </message>
    <message>
        <source>Make T%1 &amp;Active (No Probe)…</source>
        <translation>将 T%1 设为当前刀具（不测量）(&amp;A)…</translation>
    </message>
    <message>
        <source>Connect to a machine that is idle and not halted first.</source>
        <translation>请先连接一台空闲且未停机的机器。</translation>
    </message>
    <message>
        <source>Select one tool of the table.</source>
        <translation>请在表中选择一把刀具。</translation>
    </message>
    <message>
        <source>T%1 is already the active tool.</source>
        <translation>T%1 已是当前刀具。</translation>
    </message>
    <message>
        <source>Tell the machine that T%1 is in the spindle, without probing it.</source>
        <translation>告诉机器 T%1 在主轴中，不进行测量。</translation>
    </message>
    <message>
        <source>&amp;Set T%1&apos;s TLO…</source>
        <translation>设置 T%1 的 TLO(&amp;S)…</translation>
    </message>
    <message>
        <source>Set the TLO of the tool in the spindle by hand (Machine ▸ Set the offset by hand).</source>
        <translation>手动设置主轴中刀具的 TLO（机器 ▸ 手动设置补偿）。</translation>
    </message>
    <message>
        <source>Only the tool in the spindle&apos;s TLO can be set: make T%1 active first.</source>
        <translation>只能设置主轴中刀具的 TLO：请先将 T%1 设为当前刀具。</translation>
    </message>
    <message>
        <source>&amp;Restore T%1&apos;s Known TLO…</source>
        <translation>恢复 T%1 的已知 TLO(&amp;R)…</translation>
    </message>
    <message>
        <source>&amp;Restore Known TLO…</source>
        <translation>恢复已知 TLO(&amp;R)…</translation>
    </message>
    <message>
        <source>&amp;Probe T%1 (in the Spindle)</source>
        <translation>测量 T%1（在主轴中）(&amp;P)</translation>
    </message>
    <message>
        <source>&amp;Probe the Tool in the Spindle</source>
        <translation>测量主轴中的刀具(&amp;P)</translation>
    </message>
    <message>
        <source>Make T%1 active?</source>
        <translation>将 T%1 设为当前刀具？</translation>
    </message>
    <message>
        <source>Is T%1 in the spindle now?</source>
        <translation>T%1 现在在主轴中吗？</translation>
    </message>
    <message>
        <source>The machine takes T%1 as the tool in the spindle, without probing it. It keeps the TLO in force now (another tool&apos;s, or none): probe T%1 or restore its TLO before it cuts.

Sends: %2</source>
        <translation>机器将 T%1 视为主轴中的刀具，不进行测量。它保留当前生效的 TLO（另一把刀具的，或没有）：切削前请测量 T%1 或恢复其 TLO。

发送：%2</translation>
    </message>
    <message>
        <source>T%1 Is in the Spindle</source>
        <translation>T%1 在主轴中</translation>
    </message>
    <message>
        <source>T%1 was not made active</source>
        <translation>T%1 未设为当前刀具</translation>
    </message>
    <message>
        <source>The machine&apos;s tool is as it was.</source>
        <translation>机器的刀具保持不变。</translation>
    </message>
    <message>
        <source>&amp;Change to It (M6)…</source>
        <translation>换到此刀具 (M6)(&amp;C)…</translation>
    </message>
    <message>
        <source>&amp;Change to T%1 (M6)…</source>
        <translation>换到 T%1 (M6)(&amp;C)…</translation>
    </message>
    <message>
        <source>The machine&apos;s tool change to T%1, then T%1 measured on the tool setter.</source>
        <translation>机器换到 T%1，然后在对刀仪上测量 T%1。</translation>
    </message>
    <message>
        <source>The machine puts the tool in the spindle back, takes T%1 from its rack (or asks you for it when it is not in the rack) and measures it on the tool setter. Keep hands clear.</source>
        <translation>机器把主轴中的刀具放回，从刀库取出 T%1（不在刀库中时会请您装入），并在对刀仪上测量。请勿靠近。</translation>
    </message>
    <message>
        <source>The machine stops and waits for you to put T%1 in the spindle; press cycle start on the machine (or Continue here), and T%1 is measured on the tool setter. Keep hands clear.</source>
        <translation>机器停下并等待您把 T%1 装入主轴；按机器上的循环启动（或此处的继续），随后在对刀仪上测量 T%1。请勿靠近。</translation>
    </message>
    <message>
        <source>Change to T%1?</source>
        <translation>换到 T%1？</translation>
    </message>
    <message>
        <source>Change to T%1 now?</source>
        <translation>现在换到 T%1 吗？</translation>
    </message>
    <message>
        <source>Sends: M6 T%1</source>
        <translation>发送：M6 T%1</translation>
    </message>
    <message>
        <source>Change to T%1</source>
        <translation>换到 T%1</translation>
    </message>
    <message>
        <source>The change to T%1 did not finish</source>
        <translation>换到 T%1 未完成</translation>
    </message>
    <message>
        <source>Nothing was written to the tool table.</source>
        <translation>刀具表中未写入任何内容。</translation>
    </message>
    <message>
        <source>T%1 is in the spindle, measured: TLO %2, recorded in the table.</source>
        <translation>T%1 已在主轴中并已测量：TLO %2，已记入刀具表。</translation>
    </message>
    <message>
        <source>T%1 was not recorded</source>
        <translation>T%1 未记录</translation>
    </message>
    <message>
        <source>T%1 is in the spindle, but its TLO could not be recorded: %2</source>
        <translation>T%1 已在主轴中，但其 TLO 无法记录：%2</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolDocument</name>
    <message>
        <source>This table has no file yet; use Save As.</source>
        <translation>此表还没有文件；请使用“另存为”。</translation>
    </message>
    <message>
        <source>%1 is in %2 but this table is in %3; Toffee does not convert units on import.</source>
        <translation>%1 的单位为 %2，但此表为 %3；Toffee 导入时不换算单位。</translation>
    </message>
    <message>
        <source>Import %1 tools</source>
        <translation>导入 %1 把刀具</translation>
    </message>
    <message>
        <source>Measure T%1</source>
        <translation>测量 T%1</translation>
    </message>
    <message>
        <source>%1 no longer exists; saving writes it again.</source>
        <translation>%1 已不存在；保存时将重新写入。</translation>
    </message>
    <message>
        <source>%1 does not load (%2), so the recovered edits are a new table: save them with Save As.</source>
        <translation>%1 无法加载（%2），因此恢复的修改成为一个新表：请用“另存为”保存。</translation>
    </message>
    <message>
        <source>Recover unsaved edits</source>
        <translation>恢复未保存的修改</translation>
    </message>
    <message>
        <source>Keep only what %1 holds</source>
        <translation>只保留 %1 中的内容</translation>
    </message>
    <message>
        <source>Set T%1 TLO by hand</source>
        <translation>手动设置 T%1 的 TLO</translation>
    </message>
    <message>
        <source>Mark T%1 failed its break test</source>
        <translation>将 T%1 标记为未通过断刀检测</translation>
    </message>
    <message>
        <source>T%1 passed its break test</source>
        <translation>T%1 通过了断刀检测</translation>
    </message>
    <message>
        <source>Update from the library</source>
        <translation>从刀具库更新</translation>
    </message>
    <message>
        <source>Take T%1 from %2</source>
        <translation>采用 %2 的 T%1</translation>
    </message>
    <message>
        <source>New cutter in T%1</source>
        <translation>T%1 换新刀具</translation>
    </message>
    <message>
        <source>Pull T%1&apos;s TLO from the controller</source>
        <translation>从控制器拉取 T%1 的 TLO</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolLife</name>
    <message>
        <source>%1 min</source>
        <translation>%1 分钟</translation>
    </message>
    <message>
        <source>%1 uses</source>
        <translation>%1 次</translation>
    </message>
    <message>
        <source>Type the tool&apos;s life as minutes of cutting, uses (programs), or both: &quot;90 min&quot;, &quot;40 uses&quot;, &quot;90 min, 40 uses&quot;; leave it empty for no limit.</source>
        <translation>请以切削分钟数、使用次数（程序数）或两者输入刀具寿命：&quot;90 min&quot;、&quot;40 次&quot;、&quot;90 min, 40 次&quot;；留空表示无上限。</translation>
    </message>
    <message>
        <source>min</source>
        <translation>min</translation>
    </message>
    <message>
        <source>uses</source>
        <translation>次</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a tool life. %2</source>
        <translation>“%1”不是刀具寿命。%2</translation>
    </message>
    <message>
        <source>%1 of %2 min</source>
        <translation>%1 / %2 min</translation>
    </message>
    <message>
        <source>%1 of %2 uses</source>
        <translation>%1 / %2 次</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolSetter</name>
    <message>
        <source>The tool setter &quot;%1&quot; is not X,Y,ZMIN (machine coordinates in mm, e.g. 0,0,-120) nor X,Y,ZMIN,SEEK,LATCH[,BACKOFF] (feeds in mm/min, back-off in mm).</source>
        <translation>对刀仪“%1”既不是 X,Y,ZMIN（机床坐标，单位 mm，例如 0,0,-120），也不是 X,Y,ZMIN,SEEK,LATCH[,BACKOFF]（进给单位 mm/min，回退距离单位 mm）。</translation>
    </message>
    <message>
        <source>The tool setter &quot;%1&quot;: &quot;%2&quot; is not a number.</source>
        <translation>对刀仪“%1”：“%2”不是数字。</translation>
    </message>
    <message>
        <source>The tool setter&apos;s position must be machine coordinates from -%1 to %1 mm.</source>
        <translation>对刀仪的位置必须是 -%1 到 %1 mm 之间的机床坐标。</translation>
    </message>
    <message>
        <source>The tool setter&apos;s lowest Z (%1 mm) must be below the Z it lifts to (%2 mm): the search goes down.</source>
        <translation>对刀仪的最低 Z（%1 mm）必须低于抬起到的 Z（%2 mm）：搜索是向下进行的。</translation>
    </message>
    <message>
        <source>A probing feed must be more than 0 and at most %1 mm/min.</source>
        <translation>探测进给必须大于 0 且不超过 %1 mm/min。</translation>
    </message>
    <message>
        <source>The latch feed (%1 mm/min) must not be faster than the search feed (%2 mm/min): the second touch is the slow, precise one.</source>
        <translation>精测进给（%1 mm/min）不得快于搜索进给（%2 mm/min）：第二次触碰才是缓慢而精确的那次。</translation>
    </message>
    <message>
        <source>The back-off between the two touches must be more than 0 and at most %1 mm.</source>
        <translation>两次触碰之间的回退距离必须大于 0 且不超过 %1 mm。</translation>
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
        <translation>%1 的对刀仪</translation>
    </message>
    <message>
        <source>Where the tool setter is, in machine coordinates, and how Toffee touches it: it lifts to the safe Z, moves over the setter, searches down to the lowest Z at the search feed, backs off, and touches again at the latch feed.</source>
        <translation>对刀仪在机床坐标中的位置，以及 Toffee 如何触碰它：先抬起到安全 Z，移到对刀仪上方，以搜索进给向下搜索至最低 Z，回退，再以精测进给再次触碰。</translation>
    </message>
    <message>
        <source>Setter &amp;X:</source>
        <translation>对刀仪 X(&amp;X)：</translation>
    </message>
    <message>
        <source>Setter &amp;Y:</source>
        <translation>对刀仪 Y(&amp;Y)：</translation>
    </message>
    <message>
        <source>&amp;Lowest Z to search to:</source>
        <translation>搜索到的最低 Z(&amp;L)：</translation>
    </message>
    <message>
        <source>Safe Z to &amp;lift to:</source>
        <translation>抬起到的安全 Z(&amp;Z)：</translation>
    </message>
    <message>
        <source>&amp;Search feed:</source>
        <translation>搜索进给(&amp;S)：</translation>
    </message>
    <message>
        <source>L&amp;atch feed:</source>
        <translation>精测进给(&amp;A)：</translation>
    </message>
    <message>
        <source>&amp;Back-off between touches:</source>
        <translation>两次触碰之间的回退(&amp;B)：</translation>
    </message>
    <message>
        <source>From the machine</source>
        <translation>来自机器</translation>
    </message>
    <message>
        <source>Jog the spindle over the setter&apos;s centre, then take its X and Y from where the machine stands.</source>
        <translation>将主轴点动到对刀仪中心上方，然后从机器所在位置取 X 和 Y。</translation>
    </message>
    <message>
        <source>Where the machine stands: waiting for its report…</source>
        <translation>机器位置：等待其报告…</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>Jog s&amp;tep:</source>
        <translation>点动步距(&amp;T)：</translation>
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
        <translation>沿 %1 按点动步距移动机器。</translation>
    </message>
    <message>
        <source>Sto&amp;p</source>
        <translation>停止(&amp;P)</translation>
    </message>
    <message>
        <source>&amp;Use X and Y Where It Stands</source>
        <translation>使用机器当前位置的 X 和 Y(&amp;U)</translation>
    </message>
    <message>
        <source>Where the machine stands: X %1, Y %2, Z %3 mm (machine coordinates).</source>
        <translation>机器位置：X %1，Y %2，Z %3 mm（机器坐标）。</translation>
    </message>
    <message>
        <source>Jog the machine?</source>
        <translation>点动机器？</translation>
    </message>
    <message>
        <source>The machine moves each time you press a jog button.</source>
        <translation>每按一次点动按钮，机器都会移动。</translation>
    </message>
    <message>
        <source>Jog</source>
        <translation>点动</translation>
    </message>
    <message>
        <source>The setter&apos;s X and Y are where the machine stands: X %1, Y %2 mm.</source>
        <translation>对刀仪的 X 和 Y 为机器所在位置：X %1，Y %2 mm。</translation>
    </message>
    <message>
        <source>Stops the jog at once where the machine stands.</source>
        <translation>立即在机床当前位置停止点动。</translation>
    </message>
    <message>
        <source>Each press moves it by the jog step, at %1 mm/min, and Stop stops it. Keep hands clear.</source>
        <translation>每按一次，机床按点动步长以 %1 mm/min 移动，按“停止”即停下。请保持双手远离。</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolTable</name>
    <message>
        <source>there is no tool %1 in the table.</source>
        <translation>表中没有刀具 %1。</translation>
    </message>
    <message>
        <source>T%1 is not in the table.</source>
        <translation>T%1 不在表中。</translation>
    </message>
    <message>
        <source>T%1: %2 Nothing was recorded.</source>
        <translation>T%1：%2 未记录任何内容。</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolTableModel</name>
    <message>
        <source>Tool</source>
        <translation>刀具</translation>
    </message>
    <message>
        <source>Pocket</source>
        <translation>刀位</translation>
    </message>
    <message>
        <source>Description</source>
        <translation>描述</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>长度</translation>
    </message>
    <message>
        <source>Length wear</source>
        <translation>长度磨损</translation>
    </message>
    <message>
        <source>Total length</source>
        <translation>总长度</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>半径</translation>
    </message>
    <message>
        <source>Radius wear</source>
        <translation>半径磨损</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number; enter a value such as -12.345.</source>
        <translation>%1：“%2”不是数字；请输入例如 -12.345 的值。</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a whole number.</source>
        <translation>%1：“%2”不是整数。</translation>
    </message>
    <message>
        <source>this column cannot be edited.</source>
        <translation>此列不能编辑。</translation>
    </message>
    <message>
        <source>tool number %1 is already in the table; tool numbers must be unique.</source>
        <translation>刀具号 %1 已在表中；刀具号必须唯一。</translation>
    </message>
    <message>
        <source>Pocket %1 also holds %2. LinuxCNC&apos;s random tool changer needs each tool in its own pocket.</source>
        <translation>刀位 %1 中还有 %2。LinuxCNC 的随机换刀装置要求每把刀具都有自己的刀位。</translation>
    </message>
    <message>
        <source>not measured</source>
        <translation>未测量</translation>
    </message>
    <message>
        <source>%1 (by hand)</source>
        <translation>%1（手动）</translation>
    </message>
    <message>
        <source>%1 — BROKEN?</source>
        <translation>%1 — 断刀？</translation>
    </message>
    <message>
        <source>T%1 has not been measured on the tool setter.</source>
        <translation>T%1 尚未在对刀仪上测量。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was set on the machine by hand, not measured. A break test compares against it.</source>
        <translation>T%1 的 TLO %2 是在机床上手动设置的，未测量。断刀检测会与该值比较。</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was measured on the tool setter.</source>
        <translation>T%1 的 TLO %2 是在对刀仪上测得的。</translation>
    </message>
    <message>
        <source>T%1 failed its last break test: check it, replace it if it is damaged, then probe it again. It stays marked until it is probed.</source>
        <translation>T%1 未通过上次断刀检测：请检查该刀具，如有损坏请更换，然后重新对刀。在重新对刀之前，它会一直保持标记。</translation>
    </message>
    <message>
        <source>%1 (stale)</source>
        <translation>%1（已过期）</translation>
    </message>
    <message>
        <source>The tool length offset: measured on the tool setter, or set by hand (marked &quot;by hand&quot;).</source>
        <translation>刀长补偿：在对刀仪上测量，或手动设置（标有“手动”）。</translation>
    </message>
    <message>
        <source>When the TLO was measured or set.</source>
        <translation>刀长补偿测量或设置的时间。</translation>
    </message>
    <message>
        <source>TLO</source>
        <translation>TLO</translation>
    </message>
    <message>
        <source>TLO recorded</source>
        <translation>TLO 记录时间</translation>
    </message>
    <message>
        <source>T%1&apos;s cutter has cut %2 in %3 recorded program runs since it went in.</source>
        <translation>T%1 的刀具装入后已在 %3 次记录的程序运行中切削 %2。</translation>
    </message>
    <message>
        <source>It has no life limit: type one here, as &quot;90 min&quot;, &quot;40 uses&quot; or both.</source>
        <translation>它没有寿命上限：请在此输入，如 &quot;90 min&quot;、&quot;40 次&quot; 或两者。</translation>
    </message>
    <message>
        <source>Its life limit is %1.</source>
        <translation>其寿命上限为 %1。</translation>
    </message>
    <message>
        <source>It is past its limit: put in a new cutter (Edit ▸ New Cutter…).</source>
        <translation>已超过上限：请换上新刀具（编辑 ▸ 新刀具…）。</translation>
    </message>
    <message>
        <source>It is near its limit: have a new cutter ready.</source>
        <translation>已接近上限：请准备好新刀具。</translation>
    </message>
    <message>
        <source>Tool life</source>
        <translation>刀具寿命</translation>
    </message>
    <message>
        <source>%1 (pulled)</source>
        <translation>%1（读自控制器）</translation>
    </message>
    <message>
        <source>T%1&apos;s TLO %2 was read from the controller&apos;s own table (Pull Offsets), not measured by Toffee. A break test compares against it.</source>
        <translation>T%1 的 TLO %2 是从控制器自身的刀具表读取的（拉取偏置），并非 Toffee 测量。断刀检测会与它比较。</translation>
    </message>
    <message>
        <source>Probing</source>
        <translation>测量方式</translation>
    </message>
    <message>
        <source>T%1 is touched once at the setter&apos;s centre. Type &quot;X 20, 4 edges, spread 0.03&quot; for a face mill touched on each edge, off-centre.</source>
        <translation>T%1 在对刀仪中心触碰一次。输入“X 20, 4 刃, 差值 0.03”可让面铣刀在偏心位置逐刃触碰。</translation>
    </message>
    <message>
        <source>T%1 is probed so: %2.</source>
        <translation>T%1 的测量方式：%2。</translation>
    </message>
</context>
<context>
    <name>Toffee::ToolTablePanel</name>
    <message>
        <source>Filter tools</source>
        <translation>筛选刀具</translation>
    </message>
    <message>
        <source>Filter tools (number, description, notes…)</source>
        <translation>筛选刀具（编号、描述、备注…）</translation>
    </message>
    <message>
        <source>Tool table</source>
        <translation>刀具表</translation>
    </message>
    <message>
        <source>Read-only</source>
        <translation>只读</translation>
    </message>
</context>
<context>
    <name>Toffee::WearTrend</name>
    <message>
        <source>T%1 measured %2 shorter than its trend predicts (±%3): check the tip.</source>
        <translation>T%1 测得比趋势预测短 %2（±%3）：请检查刀尖。</translation>
    </message>
    <message>
        <source>T%1 measured %2 longer than its trend predicts (±%3): check that it sits right in its holder.</source>
        <translation>T%1 测得比趋势预测长 %2（±%3）：请检查其在刀柄中是否安装正确。</translation>
    </message>
</context>
<context>
    <name>Toffee::XmlText</name>
    <message>
        <source>this is not an HSM tool library Toffee reads: it has a document type declaration (&lt;!DOCTYPE&gt;), which no HSM library has and whose declarations can make reading take hours.</source>
        <translation>这不是 Toffee 可读取的 HSM 刀具库：它含有文档类型声明（&lt;!DOCTYPE&gt;），HSM 刀具库从不含有，而其中的声明可能使读取耗时数小时。</translation>
    </message>
    <message>
        <source>this is not an HSM tool library Toffee reads: &lt;%1&gt; has more than %2 attributes; an element of an HSM library has a few dozen at most.</source>
        <translation>这不是 Toffee 可读取的 HSM 刀具库：&lt;%1&gt; 的属性超过 %2 个；HSM 刀具库的元素最多只有几十个属性。</translation>
    </message>
    <message>
        <source>this is not an HSM tool library Toffee reads: &lt;%1&gt; brings the XML namespaces declared to %2; an HSM library declares one, and Toffee reads up to %3.</source>
        <translation>这不是 Toffee 可读取的 HSM 刀具库：到 &lt;%1&gt; 为止声明的 XML 命名空间达到 %2 个；HSM 刀具库只声明一个，Toffee 最多读取 %3 个。</translation>
    </message>
    <message>
        <source>this is not an HSM tool library Toffee reads: &lt;%1&gt; is nested %2 elements deep; an HSM library nests a few, and Toffee reads up to %3.</source>
        <translation>这不是 Toffee 可读取的 HSM 刀具库：&lt;%1&gt; 嵌套了 %2 层元素；HSM 刀具库只嵌套几层，Toffee 最多读取 %3 层。</translation>
    </message>
    <message>
        <source>this is not an HSM tool library Toffee reads: it is in &quot;%1&quot;, an encoding Toffee does not know; save it as UTF-16 or UTF-8.</source>
        <translation>这不是 Toffee 可读取的 HSM 刀具库：它的编码为“%1”，Toffee 不认识该编码；请将其另存为 UTF-16 或 UTF-8。</translation>
    </message>
    <message>
        <source>this is not well-formed XML: it is not valid %1 text.</source>
        <translation>这不是格式正确的 XML：它不是有效的 %1 文本。</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Toffee, the tool offset manager.</source>
        <translation>Toffee，刀具偏置管理器。</translation>
    </message>
    <message>
        <source>Connect to the machine on PORT.</source>
        <translation>连接到 PORT 上的机床。</translation>
    </message>
    <message>
        <source>Baud rate (default 115200).</source>
        <translation>波特率（默认 115200）。</translation>
    </message>
    <message>
        <source>Open the window, connect to the emulator, load the example table, probe, render once, and exit (0 when all went well).</source>
        <translation>打开窗口，连接模拟器，加载示例表，对刀，绘制一次后退出（一切正常时返回 0）。</translation>
    </message>
    <message>
        <source>Use the dark palette.</source>
        <translation>使用深色配色。</translation>
    </message>
    <message>
        <source>Language: de, zh_CN or en (default: the system&apos;s).</source>
        <translation>语言：de、zh_CN 或 en（默认跟随系统）。</translation>
    </message>
    <message>
        <source>A tool table to open.</source>
        <translation>要打开的刀具表。</translation>
    </message>
    <message>
        <source>Check the G-code PROGRAM against the table once the window is open.</source>
        <translation>窗口打开后，对照刀具表检查 G 代码程序 PROGRAM。</translation>
    </message>
    <message>
        <source>Connect to the built-in emulator, which takes a real machine&apos;s time for a tool change and a probe.</source>
        <translation>连接到内置模拟器，其换刀和对刀所需时间与真实机床相同。</translation>
    </message>
    <message>
        <source>The firmware the built-in emulator plays: community (default) or stock.</source>
        <translation>内置模拟器模拟的固件：community（默认）或 stock。</translation>
    </message>
    <message>
        <source>The history library: an SQLite file (or sqlite:PATH), or a shared one on PostgreSQL (postgresql://user@host:port/dbname; the password in ~/.pgpass).</source>
        <translation>历史库：一个 SQLite 文件（或 sqlite:路径），或 PostgreSQL 上的共享库（postgresql://user@host:port/dbname；密码放在 ~/.pgpass 中）。</translation>
    </message>
    <message>
        <source>Connect to the machine over Wi-Fi at HOST[:PORT] (port 2222 by default).</source>
        <translation>通过 Wi-Fi 连接位于 HOST[:PORT] 的机器（默认端口 2222）。</translation>
    </message>
</context>
</TS>
