<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>jumo::Bus</name>
    <message>
        <location filename="../lib/bus/bus.cpp" line="+95"/>
        <source>cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the line was closed</source>
        <translation>die Leitung wurde geschlossen</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>line lost: %1</source>
        <translation>Leitung verloren: %1</translation>
    </message>
    <message>
        <location line="+152"/>
        <source>read-only mode: %1 was not written</source>
        <translation>Nur-Lese-Modus: %1 wurde nicht geschrieben</translation>
    </message>
    <message>
        <location line="+6"/>
        <location line="+77"/>
        <source>unknown device</source>
        <translation>unbekanntes Gerät</translation>
    </message>
    <message>
        <location line="-77"/>
        <location line="+85"/>
        <source>&apos;%1&apos; is not an entry of %2</source>
        <translation>&apos;%1&apos; ist kein Eintrag von %2</translation>
    </message>
    <message>
        <location line="-75"/>
        <source>&apos;%1&apos; needs more words than one write may carry</source>
        <translation>&apos;%1&apos; benötigt mehr Wörter, als eine Schreibanfrage umfassen darf</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the line is not connected</source>
        <translation>die Leitung ist nicht verbunden</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>no %1 device on this line to read a broadcast back from</source>
        <translation>kein Gerät der Familie %1 an dieser Leitung, von dem ein Broadcast zurückgelesen werden kann</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>read-only mode: nothing is written</source>
        <translation>Nur-Lese-Modus: Es wird nichts geschrieben</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;%1&apos; is stored in EEPROM, which wears out after about 10,000 writes: it is never rewritten cyclically</source>
        <translation>&apos;%1&apos; ist im EEPROM gespeichert, das nach etwa 10.000 Schreibvorgängen verschleißt: Es wird nie zyklisch neu geschrieben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>only RAM values can be held, &apos;%1&apos; is not one</source>
        <translation>nur RAM-Werte können gehalten werden, &apos;%1&apos; gehört nicht dazu</translation>
    </message>
    <message>
        <location line="+134"/>
        <source>read-only mode</source>
        <translation>Nur-Lese-Modus</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>reply of %1 words where %2 were asked for</source>
        <translation>Antwort mit %1 Wörtern, angefordert waren %2</translation>
    </message>
    <message>
        <location line="+89"/>
        <source>exception %1</source>
        <translation>Exception %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>refused by the device: exception %1, %2</source>
        <translation>vom Gerät abgelehnt: Exception %1, %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (precondition: %1)</source>
        <translation> (Voraussetzung: %1)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not written: the line was lost</source>
        <translation>nicht geschrieben: die Leitung ging verloren</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no answer: %1</source>
        <translation>keine Antwort: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>written, but the read-back failed: %1</source>
        <translation>geschrieben, aber das Rücklesen ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+118"/>
        <source>broadcast sent; it cannot be read back</source>
        <translation>Broadcast gesendet; er kann nicht zurückgelesen werden</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>written (not read back)</source>
        <translation>geschrieben (nicht zurückgelesen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>acknowledged by the device; it cannot be read back</source>
        <translation>vom Gerät quittiert; der Wert kann nicht zurückgelesen werden</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>confirmed by read-back: %1</source>
        <translation>durch Rücklesen bestätigt: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>written, but the device reads back %1</source>
        <translation>geschrieben, aber das Gerät liefert beim Rücklesen %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>broadcast not taken by the device at address %1: it reads back %2</source>
        <translation>Broadcast vom Gerät an Adresse %1 nicht übernommen: es liefert beim Rücklesen %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>broadcast confirmed by read-back from every device</source>
        <translation>Broadcast durch Rücklesen von jedem Gerät bestätigt</translation>
    </message>
</context>
<context>
    <name>jumo::CommandLineTool</name>
    <message>
        <location filename="../app/cli/commandlinetool.cpp" line="+18"/>
        <source>Usage: jumoctl COMMAND [options] [arguments]

Commissioning and monitoring of JUMO power and process controllers over Modbus RTU.

Commands on the register maps:
  families                 list the device families and their map files
  map FAMILY --csv|--json  print a family&apos;s register map
  plan FAMILY [ID...]      show the read requests for entries of a family
  decode FAMILY ID WORD... decode raw register words as an entry

Commands on a serial line (all take --port PATH --baud N --format 8N1|8E1|8O1|8N2
--timeout MS --read-only); DEVICE is FAMILY@ADDRESS, e.g. ipc300@1:
  scan [--from A --to B]   find devices and name their family
  read DEVICE ID...        read entries once
  write DEVICE ID=VALUE... write entries, verified by reading them back
  dump DEVICE [--json]     read every readable entry once
  monitor DEVICE... --jsonl|--csv [--interval MS] [--cycles N]
                           poll continuously, one record per poll cycle

&apos;jumoctl COMMAND --help&apos; describes a command.
</source>
        <translation>Aufruf: jumoctl COMMAND [Optionen] [Argumente]

Inbetriebnahme und Überwachung von JUMO-Leistungs- und Prozessreglern über Modbus RTU.

Befehle zu den Registertabellen:
  families                 Gerätefamilien und ihre Map-Dateien auflisten
  map FAMILY --csv|--json  Registertabelle einer Gerätefamilie ausgeben
  plan FAMILY [ID...]      Leseanfragen für Einträge einer Gerätefamilie anzeigen
  decode FAMILY ID WORD... rohe Registerwörter als Eintrag dekodieren

Befehle an einer seriellen Leitung (alle mit --port PATH --baud N --format 8N1|8E1|8O1|8N2
--timeout MS --read-only); DEVICE ist FAMILY@ADDRESS, z. B. ipc300@1:
  scan [--from A --to B]   Geräte suchen und ihre Gerätefamilie benennen
  read DEVICE ID...        Einträge einmal lesen
  write DEVICE ID=VALUE... Einträge schreiben, durch Rücklesen überprüft
  dump DEVICE [--json]     jeden lesbaren Eintrag einmal lesen
  monitor DEVICE... --jsonl|--csv [--interval MS] [--cycles N]
                           fortlaufend abfragen, ein Datensatz je Abfragezyklus

&apos;jumoctl COMMAND --help&apos; beschreibt einen Befehl.
</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>warning: refused map file: %1</source>
        <translation>Warnung: Map-Datei abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>jumoctl: unknown command &apos;%1&apos;</source>
        <translation>jumoctl: unbekannter Befehl &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Try &apos;jumoctl --help&apos;.</source>
        <translation>Siehe &apos;jumoctl --help&apos;.</translation>
    </message>
</context>
<context>
    <name>jumo::CommandParser</name>
    <message>
        <location filename="../app/cli/commandparser.cpp" line="+19"/>
        <source>jumoctl %1: %2</source>
        <translation>jumoctl %1: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+17"/>
        <source>Try &apos;jumoctl %1 --help&apos;.</source>
        <translation>Siehe &apos;jumoctl %1 --help&apos;.</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>jumoctl %1: wrong number of arguments</source>
        <translation>jumoctl %1: falsche Anzahl von Argumenten</translation>
    </message>
</context>
<context>
    <name>jumo::LineCommands</name>
    <message>
        <location filename="../app/cli/linecommands.cpp" line="+65"/>
        <source>Serial port, e.g. /dev/ttyUSB0 (required).</source>
        <translation>Serielle Schnittstelle, z. B. /dev/ttyUSB0 (erforderlich).</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baud rate: 4800, 9600, 19200 or 38400 (default 9600).</source>
        <translation>Baudrate: 4800, 9600, 19200 oder 38400 (Standard 9600).</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rate</source>
        <translation>Rate</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data format: 8N1, 8E1, 8O1 or 8N2 (default 8N1).</source>
        <translation>Datenformat: 8N1, 8E1, 8O1 oder 8N2 (Standard 8N1).</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>format</source>
        <translation>Format</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Reply timeout in ms (default: derived from the baud rate and the device family).</source>
        <translation>Zeitüberschreitung für Antworten in ms (Standard: aus Baudrate und Gerätefamilie abgeleitet).</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+2"/>
        <location line="+326"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location line="-326"/>
        <source>Minimum response time configured in the devices, in ms (default 0).</source>
        <translation>In den Geräten eingestellte minimale Antwortzeit in ms (Standard 0).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Retries after a lost reply (default 2).</source>
        <translation>Wiederholungen nach einer ausgebliebenen Antwort (Standard 2).</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+326"/>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <location line="-324"/>
        <source>Never write to the line (control-room mode).</source>
        <translation>Nie auf die Leitung schreiben (Leitwarten-Modus).</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--port is required</source>
        <translation>--port ist erforderlich</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unsupported baud rate or data format: %1 %2</source>
        <translation>Baudrate oder Datenformat nicht unterstützt: %1 %2</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--timeout must be 10..60000 ms</source>
        <translation>--timeout muss 10..60000 ms sein</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--min-response must be 0..500 ms</source>
        <translation>--min-response muss 0..500 ms sein</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--retries must be 0..10</source>
        <translation>--retries muss 0..10 sein</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>&apos;%1&apos; is not a device: use FAMILY@ADDRESS, e.g. ipc300@1 (families: %2)</source>
        <translation>&apos;%1&apos; ist kein Gerät: FAMILY@ADDRESS verwenden, z. B. ipc300@1 (Gerätefamilien: %2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>device address %1 is outside 1..255</source>
        <translation>Geräteadresse %1 liegt außerhalb von 1..255</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Finds devices on the line and names their family.</source>
        <translation>Sucht Geräte an der Leitung und benennt ihre Gerätefamilie.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>First address (default 1).</source>
        <translation>Erste Adresse (Standard 1).</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <source>address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Last address (default 247).</source>
        <translation>Letzte Adresse (Standard 247).</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--from and --to must be addresses 1..255, from &lt;= to</source>
        <translation>--from und --to müssen Adressen 1..255 sein, from &lt;= to</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>scanning address %1 (%2 of %3)</source>
        <translation>Adresse %1 wird abgefragt (%2 von %3)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>address %1 answers, but matches no known family</source>
        <translation>Adresse %1 antwortet, passt aber zu keiner bekannten Gerätefamilie</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n device(s) found</source>
        <translation>
            <numerusform>%n Gerät gefunden</numerusform>
            <numerusform>%n Geräte gefunden</numerusform>
        </translation>
    </message>
    <message>
        <location line="+36"/>
        <source>exception %1: %2</source>
        <translation>Exception %1: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Reads every readable entry of a device once.</source>
        <translation>Liest jeden lesbaren Eintrag eines Geräts einmal.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reads entries of a device once.</source>
        <translation>Liest Einträge eines Geräts einmal.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>JSON array of {family, address, id, label, register, value, unit, status}.</source>
        <translation>JSON-Array aus {family, address, id, label, register, value, unit, status}.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FAMILY@ADDRESS, e.g. ipc300@1.</source>
        <translation>FAMILY@ADDRESS, z. B. ipc300@1.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Entry ids.</source>
        <translation>Kennungen der Einträge.</translation>
    </message>
    <message>
        <location line="+17"/>
        <location line="+77"/>
        <source>&apos;%1&apos; is not an entry of %2</source>
        <translation>&apos;%1&apos; ist kein Eintrag von %2</translation>
    </message>
    <message>
        <location line="-73"/>
        <source>&apos;%1&apos; is write-only</source>
        <translation>&apos;%1&apos; ist nur schreibbar</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>some entries could not be read</source>
        <translation>einige Einträge konnten nicht gelesen werden</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Writes entries of a device; each write is verified by reading it back.</source>
        <translation>Schreibt Einträge eines Geräts; jeder Schreibvorgang wird durch Rücklesen überprüft.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>For a broadcast (FAMILY@0): the addresses to read it back from, e.g. 1,2,5.</source>
        <translation>Bei einem Broadcast (FAMILY@0): die Adressen, von denen zurückgelesen wird, z. B. 1,2,5.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>addresses</source>
        <translation>Adressen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FAMILY@ADDRESS, or FAMILY@0 for a broadcast.</source>
        <translation>FAMILY@ADDRESS oder FAMILY@0 für einen Broadcast.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ID=VALUE, e.g. input_setpoint=42.5.</source>
        <translation>ID=VALUE, z. B. input_setpoint=42.5.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;%1&apos; is not a device: use FAMILY@ADDRESS</source>
        <translation>&apos;%1&apos; ist kein Gerät: FAMILY@ADDRESS verwenden</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--verify takes addresses 1..255, not &apos;%1&apos;</source>
        <translation>--verify erwartet Adressen 1..255, nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a broadcast is not answered: name the devices to read it back from with --verify</source>
        <translation>ein Broadcast wird nicht beantwortet: die Geräte, von denen zurückgelesen werden soll, mit --verify angeben</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;%1&apos; is not ID=VALUE</source>
        <translation>&apos;%1&apos; hat nicht die Form ID=VALUE</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Polls devices continuously and prints every poll cycle.</source>
        <translation>Fragt Geräte fortlaufend ab und gibt jeden Abfragezyklus aus.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Poll interval per device in ms (default 0: as fast as the line allows).</source>
        <translation>Abfrageintervall je Gerät in ms (Standard 0: so schnell, wie die Leitung es erlaubt).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop after this many cycles of every device (default: run until stopped).</source>
        <translation>Nach so vielen Zyklen jedes Geräts anhalten (Standard: bis zum Abbruch laufen).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Comma-separated entry ids to poll (default: all readable entries).</source>
        <translation>Kommagetrennte Kennungen der abzufragenden Einträge (Standard: alle lesbaren Einträge).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ids</source>
        <translation>Kennungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>One JSON object per completed poll cycle of a device.</source>
        <translation>Ein JSON-Objekt je abgeschlossenem Abfragezyklus eines Geräts.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV rows: time,device,id,value,unit,status.</source>
        <translation>CSV-Zeilen: time,device,id,value,unit,status.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>FAMILY@ADDRESS.</source>
        <translation>FAMILY@ADDRESS.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>jumoctl monitor: give exactly one of --jsonl and --csv</source>
        <translation>jumoctl monitor: genau eine der Optionen --jsonl und --csv angeben</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--interval must be a number of ms &gt;= 0</source>
        <translation>--interval muss eine Anzahl ms &gt;= 0 sein</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--cycles must be a number &gt;= 0</source>
        <translation>--cycles muss eine Zahl &gt;= 0 sein</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;%1&apos; is not a readable entry of %2</source>
        <translation>&apos;%1&apos; ist kein lesbarer Eintrag von %2</translation>
    </message>
</context>
<context>
    <name>jumo::MapCommands</name>
    <message>
        <location filename="../app/cli/mapcommands.cpp" line="+132"/>
        <source>unknown family &apos;%1&apos; (known: %2)</source>
        <translation>unbekannte Gerätefamilie &apos;%1&apos; (bekannt: %2)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Lists the device families and the map files they come from.</source>
        <translation>Listet die Gerätefamilien und die Map-Dateien auf, aus denen sie stammen.</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n registers</source>
        <translation>
            <numerusform>%n Register</numerusform>
            <numerusform>%n Register</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>refused map file: %1</source>
        <translation>Map-Datei abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>Prints the register map of a device family.</source>
        <translation>Gibt die Registertabelle einer Gerätefamilie aus.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Family id, see &apos;jumoctl families&apos;.</source>
        <translation>Kennung der Gerätefamilie, siehe &apos;jumoctl families&apos;.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV: one row per register and one per bit of a bit field.</source>
        <translation>CSV: eine Zeile je Register und je Bit eines Bitfelds.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>JSON: the family&apos;s facts and every register.</source>
        <translation>JSON: die Angaben zur Gerätefamilie und alle Register.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>jumoctl map: give exactly one of --csv and --json</source>
        <translation>jumoctl map: genau eine der Optionen --csv und --json angeben</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Shows the read requests that poll the given entries (all readable entries if none).</source>
        <translation>Zeigt die Leseanfragen, mit denen die angegebenen Einträge abgefragt werden (ohne Angabe alle lesbaren Einträge).</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+28"/>
        <source>Family id.</source>
        <translation>Kennung der Gerätefamilie.</translation>
    </message>
    <message>
        <location line="-27"/>
        <source>Entry ids to read.</source>
        <translation>Kennungen der zu lesenden Einträge.</translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>read %1..%2 (%n words): </source>
        <translation>
            <numerusform>lesen %1..%2 (%n Wort): </numerusform>
            <numerusform>lesen %1..%2 (%n Wörter): </numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%n requests, </source>
        <translation>
            <numerusform>%n Anfrage, </numerusform>
            <numerusform>%n Anfragen, </numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+0"/>
        <source>%n words</source>
        <translation>
            <numerusform>%n Wort</numerusform>
            <numerusform>%n Wörter</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Decodes raw register words (hex, as read from the device) as an entry.</source>
        <translation>Dekodiert rohe Registerwörter (hexadezimal, wie vom Gerät gelesen) als Eintrag.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Entry id.</source>
        <translation>Kennung des Eintrags.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Register words in hex, e.g. 70A3 4145.</source>
        <translation>Registerwörter hexadezimal, z. B. 70A3 4145.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;%1&apos; is not an entry of %2</source>
        <translation>&apos;%1&apos; ist kein Eintrag von %2</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;%1&apos; is not a 16-bit hex word</source>
        <translation>&apos;%1&apos; ist kein 16-Bit-Hexwort</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;%1&apos; takes %2 words, %3 given</source>
        <translation>&apos;%1&apos; benötigt %2 Wörter, %3 angegeben</translation>
    </message>
</context>
<context>
    <name>jumo::MapLoader</name>
    <message>
        <location filename="../lib/maploader.cpp" line="+47"/>
        <source>malformed JSON at byte %1: %2</source>
        <translation>fehlerhaftes JSON bei Byte %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the top level must be a JSON object</source>
        <translation>die oberste Ebene muss ein JSON-Objekt sein</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>unknown key &apos;%1&apos;</source>
        <translation>unbekannter Schlüssel &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;%1&apos; is missing or not a non-empty string</source>
        <translation>&apos;%1&apos; fehlt oder ist keine nicht leere Zeichenkette</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;%1&apos; must be a whole number</source>
        <translation>&apos;%1&apos; muss eine ganze Zahl sein</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&apos;%1&apos; is missing</source>
        <translation>&apos;%1&apos; fehlt</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;%1&apos; must be a number</source>
        <translation>&apos;%1&apos; muss eine Zahl sein</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;%1&apos; must be 0x followed by 4 hex digits, not &apos;%2&apos;</source>
        <translation>&apos;%1&apos; muss 0x gefolgt von 4 Hexziffern sein, nicht &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;%1&apos; must be a non-empty array of numbers</source>
        <translation>&apos;%1&apos; muss ein nicht leeres Array von Zahlen sein</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; must contain only numbers</source>
        <translation>&apos;%1&apos; darf nur Zahlen enthalten</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&apos;format&apos; must be 1</source>
        <translation>&apos;format&apos; muss 1 sein</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>family id &apos;%1&apos; must be lower case letters, digits and &apos;_&apos;</source>
        <translation>Familienkennung &apos;%1&apos; darf nur aus Kleinbuchstaben, Ziffern und &apos;_&apos; bestehen</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&apos;entries&apos; must be a non-empty array</source>
        <translation>&apos;entries&apos; muss ein nicht leeres Array sein</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>&apos;protocol&apos; must be an object</source>
        <translation>&apos;protocol&apos; muss ein Objekt sein</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&apos;maxReadWords&apos; must be 1..127, not %1</source>
        <translation>&apos;maxReadWords&apos; muss 1..127 sein, nicht %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;maxWriteWords&apos; must be 1..127, not %1</source>
        <translation>&apos;maxWriteWords&apos; muss 1..127 sein, nicht %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; must be ABCD, CDAB, BADC or DCBA, not &apos;%2&apos;</source>
        <translation>&apos;%1&apos; muss ABCD, CDAB, BADC oder DCBA sein, nicht &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>unknown data format &apos;%1&apos;</source>
        <translation>unbekanntes Datenformat &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;dataFormats&apos; must list at least one format</source>
        <translation>&apos;dataFormats&apos; muss mindestens ein Format enthalten</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>address range %1..%2 is not within 1..255</source>
        <translation>Adressbereich %1..%2 liegt nicht innerhalb von 1..255</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;processingTimeMaxMs&apos; is missing or negative</source>
        <translation>&apos;processingTimeMaxMs&apos; fehlt oder ist negativ</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;identify&apos; must be a non-empty array of probes</source>
        <translation>&apos;identify&apos; muss ein nicht leeres Array von Prüfabfragen sein</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>a probe needs exactly one of textContains, maskNonZero, answers, exception</source>
        <translation>eine Prüfabfrage benötigt genau eines von textContains, maskNonZero, answers, exception</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;words&apos; must be 1..125</source>
        <translation>&apos;words&apos; muss 1..125 sein</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;exceptions&apos; must be an object mapping codes to meanings</source>
        <translation>&apos;exceptions&apos; muss ein Objekt sein, das Codes ihren Bedeutungen zuordnet</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;%1&apos; is not an exception code with a text</source>
        <translation>&apos;%1&apos; ist kein Exception-Code mit Text</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;errorValues&apos; must be an object or null</source>
        <translation>&apos;errorValues&apos; muss ein Objekt oder null sein</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>entry #%1</source>
        <translation>Eintrag #%1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>an entry must be an object</source>
        <translation>ein Eintrag muss ein Objekt sein</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>entry #%1 (%2)</source>
        <translation>Eintrag #%1 (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+246"/>
        <location line="+21"/>
        <source>entry &apos;%1&apos; (%2)</source>
        <translation>Eintrag &apos;%1&apos; (%2)</translation>
    </message>
    <message>
        <location line="-257"/>
        <source>id must be lower case letters, digits and &apos;_&apos;</source>
        <translation>die Kennung darf nur aus Kleinbuchstaben, Ziffern und &apos;_&apos; bestehen</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>unknown type &apos;%1&apos; (expected float, int16, uint16, int32, uint32, bool, enum, bitfield or text)</source>
        <translation>unbekannter Typ &apos;%1&apos; (erwartet: float, int16, uint16, int32, uint32, bool, enum, bitfield oder text)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unknown access &apos;%1&apos; (expected R, W or RW)</source>
        <translation>unbekannter Zugriff &apos;%1&apos; (erwartet: R, W oder RW)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>unknown storage &apos;%1&apos; (expected RAM or EEPROM)</source>
        <translation>unbekannter Speicherort &apos;%1&apos; (erwartet: RAM oder EEPROM)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a read-only entry cannot have a storage</source>
        <translation>ein nur lesbarer Eintrag kann keinen Speicherort haben</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a text needs &apos;bytes&apos; (at least 2, including the NUL)</source>
        <translation>ein Text benötigt &apos;bytes&apos; (mindestens 2, einschließlich des NUL)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;bytes&apos; is only for texts</source>
        <translation>&apos;bytes&apos; ist nur für Texte zulässig</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;words&apos; is only for reserved blocks and must be at least 1</source>
        <translation>&apos;words&apos; ist nur für reservierte Blöcke zulässig und muss mindestens 1 sein</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;min&apos; is greater than &apos;max&apos;</source>
        <translation>&apos;min&apos; ist größer als &apos;max&apos;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>unknown control &apos;%1&apos;</source>
        <translation>unbekanntes Bedienelement &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a control needs a writable entry</source>
        <translation>ein Bedienelement benötigt einen schreibbaren Eintrag</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>&apos;values&apos; is only for enums</source>
        <translation>&apos;values&apos; ist nur für Enums zulässig</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>an enum needs &apos;values&apos;</source>
        <translation>ein Enum benötigt &apos;values&apos;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>enum value &apos;%1&apos; must be a number 0..65535 with a text</source>
        <translation>Enum-Wert &apos;%1&apos; muss eine Zahl 0..65535 mit einem Text sein</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;bits&apos; is only for bit fields</source>
        <translation>&apos;bits&apos; ist nur für Bitfelder zulässig</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a bit field needs &apos;bits&apos;</source>
        <translation>ein Bitfeld benötigt &apos;bits&apos;</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1, bit %2</source>
        <translation>%1, Bit %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bit number must be 0..15</source>
        <translation>Bitnummer muss 0..15 sein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bit field of width %1 does not fit in 16 bits</source>
        <translation>Bitfeld der Breite %1 passt nicht in 16 Bit</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a bit needs an id of lower case letters, digits and &apos;_&apos;</source>
        <translation>ein Bit benötigt eine Kennung aus Kleinbuchstaben, Ziffern und &apos;_&apos;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>duplicate bit id &apos;%1&apos;</source>
        <translation>doppelte Bitkennung &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a bit needs a label</source>
        <translation>ein Bit benötigt eine Bezeichnung</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>unknown kind &apos;%1&apos; (expected alarm, warning, status or command)</source>
        <translation>unbekannte Art &apos;%1&apos; (erwartet: alarm, warning, status oder command)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>bit defined twice</source>
        <translation>Bit doppelt definiert</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>refers to unknown entry &apos;%1&apos;</source>
        <translation>verweist auf unbekannten Eintrag &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>refers to unknown bit &apos;%1&apos; of &apos;%2&apos;</source>
        <translation>verweist auf unbekanntes Bit &apos;%1&apos; von &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>unknown model &apos;%1&apos; (expected power_controller or process_controller)</source>
        <translation>unbekanntes Modell &apos;%1&apos; (erwartet: power_controller oder process_controller)</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>a limit needs &apos;above&apos; or &apos;below&apos; (an entry id or a number)</source>
        <translation>ein Grenzwert benötigt &apos;above&apos; oder &apos;below&apos; (eine Eintragskennung oder eine Zahl)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>unknown action &apos;%1&apos;</source>
        <translation>unbekannte Aktion &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>duplicate id (also at %1)</source>
        <translation>doppelte Kennung (auch bei %1)</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+2"/>
        <source>entry &apos;%1&apos;</source>
        <translation>Eintrag &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>alias of unknown entry &apos;%1&apos;</source>
        <translation>Alias eines unbekannten Eintrags &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>runs past address 0xFFFF</source>
        <translation>reicht über Adresse 0xFFFF hinaus</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>words %1..%2 overlap entry &apos;%3&apos; (%4..%5)</source>
        <translation>Wörter %1..%2 überschneiden sich mit Eintrag &apos;%3&apos; (%4..%5)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1: cannot open: %2</source>
        <translation>%1: kann nicht geöffnet werden: %2</translation>
    </message>
</context>
<context>
    <name>jumo::PtyPair</name>
    <message>
        <location filename="../lib/sim/ptypair.cpp" line="+15"/>
        <source>cannot start socat (is it installed?): %1</source>
        <translation>socat kann nicht gestartet werden (ist es installiert?): %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>socat ended: %1</source>
        <translation>socat beendet: %1</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>socat did not create the pseudo-terminals</source>
        <translation>socat hat die Pseudo-Terminals nicht angelegt</translation>
    </message>
</context>
<context>
    <name>jumo::ReadPlanner</name>
    <message>
        <location filename="../lib/readplanner.cpp" line="+32"/>
        <source>&apos;%1&apos; is not an entry of %2</source>
        <translation>&apos;%1&apos; ist kein Eintrag von %2</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>&apos;%1&apos; (%2) is write-only</source>
        <translation>&apos;%1&apos; (%2) ist nur schreibbar</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; (%2) spans words that are not all readable</source>
        <translation>&apos;%1&apos; (%2) umfasst Wörter, die nicht alle lesbar sind</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;%1&apos; (%2) has %3 words, more than the %4 words one read may take</source>
        <translation>&apos;%1&apos; (%2) hat %3 Wörter, mehr als die %4 Wörter, die eine Leseanfrage umfassen darf</translation>
    </message>
</context>
<context>
    <name>jumo::RegisterMap</name>
    <message>
        <location filename="../lib/registermap.cpp" line="+142"/>
        <source>exception %1 (not documented for this family)</source>
        <translation>Exception-Code %1 (für diese Gerätefamilie nicht dokumentiert)</translation>
    </message>
</context>
<context>
    <name>jumo::RegisterMapBrowser</name>
    <message>
        <location filename="../ui/registermapbrowser.cpp" line="+18"/>
        <source>JUMO register maps</source>
        <translation>JUMO-Registertabellen</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>No register maps could be loaded.</source>
        <translation>Es konnten keine Registertabellen geladen werden.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 - %2 registers - models: %3 - manual: %4</source>
        <translation>%1 - %2 Register - Modelle: %3 - Handbuch: %4</translation>
    </message>
</context>
<context>
    <name>jumo::RegisterMapModel</name>
    <message>
        <location filename="../lib/registermapmodel.cpp" line="+36"/>
        <source>Correction of the manual: %1</source>
        <translation>Korrektur des Handbuchs: %1</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Id</source>
        <translation>Kennung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Label</source>
        <translation>Bezeichnung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type</source>
        <translation>Typ</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Access</source>
        <translation>Zugriff</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Storage</source>
        <translation>Speicherort</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Section</source>
        <translation>Abschnitt</translation>
    </message>
</context>
<context>
    <name>jumo::ValueCodec</name>
    <message>
        <location filename="../lib/valuecodec.cpp" line="+88"/>
        <source>Underrange</source>
        <translation>Unterlauf</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Overrange</source>
        <translation>Überlauf</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Invalid</source>
        <translation>Ungültig</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Decode error</source>
        <translation>Dekodierfehler</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>expected %1 words, got %2</source>
        <translation>%1 Wörter erwartet, %2 erhalten</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>not a boolean: %1</source>
        <translation>kein boolescher Wert: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>unknown value %1</source>
        <translation>unbekannter Wert %1</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>&apos;%1&apos; is read-only</source>
        <translation>&apos;%1&apos; ist nur lesbar</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no value given for &apos;%1&apos;</source>
        <translation>kein Wert für &apos;%1&apos; angegeben</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is outside the range of &apos;%2&apos; (%3 to %4)</source>
        <translation>%1 liegt außerhalb des Bereichs von &apos;%2&apos; (%3 bis %4)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;%1&apos; is not a whole number</source>
        <translation>&apos;%1&apos; ist keine ganze Zahl</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 does not fit the type of &apos;%2&apos; (%3 to %4)</source>
        <translation>%1 passt nicht zum Typ von &apos;%2&apos; (%3 bis %4)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&apos;%1&apos; is not a number</source>
        <translation>&apos;%1&apos; ist keine Zahl</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is too large for a float</source>
        <translation>%1 ist zu groß für einen float</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>&apos;%1&apos; is not a boolean (0/1, on/off, true/false)</source>
        <translation>&apos;%1&apos; ist kein boolescher Wert (0/1, on/off, true/false)</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>&apos;%1&apos; is not a value of &apos;%2&apos; (%3)</source>
        <translation>&apos;%1&apos; ist kein Wert von &apos;%2&apos; (%3)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 does not fit in 16 bits</source>
        <translation>%1 passt nicht in 16 Bit</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;%1&apos; is not a bit of &apos;%2&apos;</source>
        <translation>&apos;%1&apos; ist kein Bit von &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the text for &apos;%1&apos; must be at most %2 Latin-1 characters</source>
        <translation>der Text für &apos;%1&apos; darf höchstens %2 Latin-1-Zeichen lang sein</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/jumo-hmi.cpp" line="+19"/>
        <source>JUMO commissioning and monitoring HMI.</source>
        <translation>JUMO-HMI für Inbetriebnahme und Überwachung.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Start on the built-in simulated bus (one device of each family).</source>
        <translation>Auf dem eingebauten simulierten Bus starten (ein Gerät jeder Familie).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Control-room mode: nothing is ever written to the devices.</source>
        <translation>Leitwarten-Modus: Es wird nie etwas auf die Geräte geschrieben.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Map files refused</source>
        <translation>Map-Dateien abgelehnt</translation>
    </message>
    <message>
        <location filename="../app/jumo-sim.cpp" line="+24"/>
        <source>Simulated JUMO devices on a serial line. DEVICE is FAMILY@ADDRESS, e.g. ipc300@1.</source>
        <translation>Simulierte JUMO-Geräte an einer seriellen Leitung. DEVICE ist FAMILY@ADDRESS, z. B. ipc300@1.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Serial port to serve.</source>
        <translation>Zu bedienende serielle Schnittstelle.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Make a pseudo-terminal pair in this folder (needs socat); clients connect to FOLDER/master.</source>
        <translation>Ein Pseudo-Terminal-Paar in diesem Ordner anlegen (benötigt socat); Clients verbinden sich mit FOLDER/master.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Baud rate (default 9600).</source>
        <translation>Baudrate (Standard 9600).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data format (default 8N1).</source>
        <translation>Datenformat (Standard 8N1).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Processing delay before each reply in ms (default 2).</source>
        <translation>Verarbeitungsverzögerung vor jeder Antwort in ms (Standard 2).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Minimum response time in ms (default 0).</source>
        <translation>Minimale Antwortzeit in ms (Standard 0).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Delay replies by their wire time at the baud rate.</source>
        <translation>Antworten um ihre Übertragungsdauer bei der Baudrate verzögern.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Devices to simulate.</source>
        <translation>Zu simulierende Geräte.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unsupported baud rate or data format</source>
        <translation>Baudrate oder Datenformat nicht unterstützt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>give exactly one of --port and --pty</source>
        <translation>genau eine der Optionen --port und --pty angeben</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>refused map file: %1</source>
        <translation>Map-Datei abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>name at least one device, e.g. ipc300@1</source>
        <translation>mindestens ein Gerät angeben, z. B. ipc300@1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;%1&apos; is not FAMILY@ADDRESS with a known family</source>
        <translation>&apos;%1&apos; ist nicht FAMILY@ADDRESS mit einer bekannten Gerätefamilie</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>serving %n device(s) on %1</source>
        <translation>
            <numerusform>bedient %n Gerät an %1</numerusform>
            <numerusform>bedient %n Geräte an %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>connect to %1</source>
        <translation>verbinden mit %1</translation>
    </message>
</context>
</TS>
