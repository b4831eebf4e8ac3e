<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de_DE">
<context>
    <name>QModbusClient</name>
    <message>
        <location filename="../lib/protocol/translations.cpp" line="+38"/>
        <source>Request timeout.</source>
        <translation>Zeitüberschreitung der Anfrage.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reply aborted due to connection closure.</source>
        <translation>Antwort abgebrochen, weil die Verbindung geschlossen wurde.</translation>
    </message>
</context>
<context>
    <name>QModbusDevice</name>
    <message>
        <location line="-10"/>
        <source>Referenced serial device does not exist.</source>
        <translation>Das angegebene serielle Gerät existiert nicht.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cannot open serial device due to permissions.</source>
        <translation>Das serielle Gerät kann wegen fehlender Berechtigung nicht geöffnet werden.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cannot open serial device.</source>
        <translation>Das serielle Gerät kann nicht geöffnet werden.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write error.</source>
        <translation>Schreibfehler.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read error.</source>
        <translation>Lesefehler.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resource error.</source>
        <translation>Ressourcenfehler.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device operation is not supported error.</source>
        <translation>Der Vorgang wird vom Gerät nicht unterstützt.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timeout error.</source>
        <translation>Zeitüberschreitung.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unknown error.</source>
        <translation>Unbekannter Fehler.</translation>
    </message>
</context>
<context>
    <name>jumo::AddDeviceDialog</name>
    <message>
        <location filename="../ui/adddevicedialog.cpp" line="+15"/>
        <source>Add device</source>
        <translation>Gerät hinzufügen</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&amp;Line:</source>
        <translation>&amp;Leitung:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Family:</source>
        <translation>&amp;Familie:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Address:</source>
        <translation>&amp;Adresse:</translation>
    </message>
</context>
<context>
    <name>jumo::AlarmBitsModel</name>
    <message>
        <location filename="../lib/models/alarmbitsmodel.cpp" line="+112"/>
        <source>%1 (register %2)</source>
        <translation>%1 (Register %2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1
Register %2 (%3), bit %4, %5
Manual %6: &quot;%7&quot;</source>
        <translation>%1
Register %2 (%3), Bit %4, %5
Handbuch %6: &quot;%7&quot;</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Unknown: the register could not be read (%1).</source>
        <translation>Unbekannt: Das Register konnte nicht gelesen werden (%1).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Stale: not read within the device&apos;s cycle.</source>
        <translation>Veraltet: nicht innerhalb des Gerätezyklus gelesen.</translation>
    </message>
</context>
<context>
    <name>jumo::BitSwitches</name>
    <message>
        <location filename="../ui/bitswitches.cpp" line="+43"/>
        <source>The device does not report these bits: a write sets every bit as ticked here.</source>
        <translation>Das Gerät meldet diese Bits nicht zurück: Ein Schreiben setzt jedes Bit so, wie es hier angekreuzt ist.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>unknown: the device cannot be read</source>
        <translation>unbekannt: das Gerät kann nicht gelesen werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>stale</source>
        <translation>veraltet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>on</source>
        <translation>ein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bit %1 of %2, %3; reported in %4</source>
        <translation>Bit %1 von %2, %3; gemeldet in %4</translation>
    </message>
</context>
<context>
    <name>jumo::BitWrite</name>
    <message>
        <location filename="../lib/protocol/bitwrite.cpp" line="+66"/>
        <source>&apos;%1&apos; is not a writable bit field</source>
        <translation>&apos;%1&apos; ist kein beschreibbares Bitfeld</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos; is a command word: its bits are actions, sent one at a time, not states to keep</source>
        <translation>&apos;%1&apos; ist ein Befehlswort: Seine Bits sind Aktionen, die einzeln gesendet werden, keine Zustände, die erhalten bleiben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no bit of &apos;%1&apos; given</source>
        <translation>kein Bit von &apos;%1&apos; angegeben</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; is not a bit of &apos;%2&apos;</source>
        <translation>&apos;%1&apos; ist kein Bit von &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1.%2&apos; is %3 bits wide; write the whole word</source>
        <translation>&apos;%1.%2&apos; ist %3 Bit breit; schreiben Sie das ganze Wort</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1.%2&apos; is the activation bit, which every write sets</source>
        <translation>&apos;%1.%2&apos; ist das Aktivierungsbit, das jeder Schreibvorgang setzt</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the device does not report the state of %1 of &apos;%2&apos;, which a write of the word sets too: give every bit, or write the whole word</source>
        <translation>das Gerät meldet den Zustand von %1 von &apos;%2&apos; nicht, den ein Schreiben des Wortes ebenfalls setzt: Geben Sie jedes Bit an oder schreiben Sie das ganze Wort</translation>
    </message>
</context>
<context>
    <name>jumo::BroadcastClearance</name>
    <message>
        <location filename="../lib/bus/broadcastclearance.cpp" line="+17"/>
        <source>not broadcast: address %1 answers as %2, and the words of %3 mean something else to it</source>
        <translation>nicht rundgesendet: an Adresse %1 antwortet ein %2, und die Wörter von %3 bedeuten für ihn etwas anderes</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not broadcast: a device of no known family answers at address %1</source>
        <translation>nicht rundgesendet: an Adresse %1 antwortet ein Gerät keiner bekannten Familie</translation>
    </message>
</context>
<context>
    <name>jumo::BroadcastGate</name>
    <message>
        <location filename="../app/cli/broadcastgate.cpp" line="+25"/>
        <source>For a broadcast: scan addresses %1..%2 first and send only if every device found is of the family; it is read back from them unless --verify names some.</source>
        <translation>Für einen Broadcast: zuerst die Adressen %1..%2 absuchen und nur senden, wenn jedes gefundene Gerät zur Familie gehört; zurückgelesen wird von ihnen, sofern --verify keine nennt.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>For a broadcast: state that every device on the line is of this family (recorded in the audit log).</source>
        <translation>Für einen Broadcast: erklären, dass jedes Gerät an der Leitung zu dieser Familie gehört (im Audit-Protokoll vermerkt).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>family</source>
        <translation>Familie</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--line-has-only names %1, the broadcast is for %2</source>
        <translation>--line-has-only nennt %1, der Broadcast gilt %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a broadcast reaches every device on the line, and the words of %1 mean something else to other families: give --scan-first to scan the line for other devices first, or --line-has-only %1 if you know there are none</source>
        <translation>ein Broadcast erreicht jedes Gerät an der Leitung, und die Wörter von %1 bedeuten für andere Familien etwas anderes: --scan-first sucht die Leitung zuerst nach anderen Geräten ab, --line-has-only %1 erklärt, dass es keine gibt</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a broadcast is not answered: name the devices to read it back from with --verify</source>
        <translation>ein Broadcast wird nicht beantwortet: nennen Sie mit --verify die Geräte, von denen er zurückgelesen wird</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>no broadcast through a Modbus TCP gateway: what a gateway makes of address 0 differs from gateway to gateway; write to each device instead</source>
        <translation>kein Broadcast über ein Modbus-TCP-Gateway: was ein Gateway mit Adresse 0 macht, ist von Gateway zu Gateway verschieden; schreiben Sie stattdessen jedes Gerät einzeln</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>the user stated that every device on the line is a %1 (--line-has-only %1)</source>
        <translation>der Benutzer hat erklärt, dass jedes Gerät an der Leitung ein %1 ist (--line-has-only %1)</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>scanning address %1 of %2 before the broadcast</source>
        <translation>durchsuche Adresse %1 von %2 vor dem Broadcast</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>not broadcast: the scan found no %1 at address %2 to read it back from</source>
        <translation>nicht rundgesendet: die Suche fand an Adresse %2 kein %1 zum Zurücklesen</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>not broadcast: the scan found no %1 on the line</source>
        <translation>nicht rundgesendet: die Suche fand kein %1 an der Leitung</translation>
    </message>
</context>
<context>
    <name>jumo::Bus</name>
    <message>
        <location filename="../lib/bus/bus.cpp" line="+102"/>
        <location line="+1"/>
        <source>the line was closed</source>
        <translation>die Leitung wurde geschlossen</translation>
    </message>
    <message>
        <location filename="../lib/bus/requestdesk.cpp" line="+13"/>
        <location line="+109"/>
        <source>read-only mode: %1 was not written</source>
        <translation>Nur-Lese-Modus: %1 wurde nicht geschrieben</translation>
    </message>
    <message>
        <location line="-105"/>
        <location line="+167"/>
        <source>unknown device</source>
        <translation>unbekanntes Gerät</translation>
    </message>
    <message>
        <location line="-163"/>
        <location line="+170"/>
        <source>&apos;%1&apos; is not an entry of %2</source>
        <translation>&apos;%1&apos; ist kein Eintrag von %2</translation>
    </message>
    <message>
        <location line="-156"/>
        <source>not written: %1</source>
        <translation>nicht geschrieben: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>not written: %1 is not yet confirmed to be a %2 (its identity is checked when it answers)</source>
        <translation>nicht geschrieben: %1 ist noch nicht als %2 bestätigt (die Identität wird geprüft, sobald das Gerät antwortet)</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>&apos;%1&apos; needs more words than one write may carry</source>
        <translation>&apos;%1&apos; benötigt mehr Wörter, als eine Schreibanfrage umfassen darf</translation>
    </message>
    <message>
        <location filename="../lib/bus/bus.cpp" line="-13"/>
        <location line="+22"/>
        <source>the line was reopened</source>
        <translation>die Leitung wurde neu geöffnet</translation>
    </message>
    <message>
        <location filename="../lib/bus/requestdesk.cpp" line="+4"/>
        <location line="+31"/>
        <location line="+70"/>
        <source>not written: the line is not connected</source>
        <translation>nicht geschrieben: Die Leitung ist nicht verbunden</translation>
    </message>
    <message>
        <location line="-39"/>
        <source>not broadcast: a Modbus TCP gateway&apos;s handling of address 0 differs from gateway to gateway; write to each device instead</source>
        <translation>kein Broadcast: was ein Modbus-TCP-Gateway mit Adresse 0 macht, ist von Gateway zu Gateway verschieden; schreiben Sie stattdessen jedes Gerät einzeln</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not broadcast: the line also has a %1 device at address %2, which would take the same words as something else</source>
        <translation>kein Broadcast: an der Leitung hängt auch ein Gerät der Familie %1 an Adresse %2, das dieselben Wörter als etwas anderes übernehmen würde</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not broadcast: %1 is not confirmed to be a %2</source>
        <translation>nicht als Broadcast gesendet: %1 ist nicht als %2 bestätigt</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>no %1 device on this line to read a broadcast back from</source>
        <translation>kein Gerät der Familie %1 an dieser Leitung, von dem ein Broadcast zurückgelesen werden kann</translation>
    </message>
    <message>
        <location line="+24"/>
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
        <location line="+5"/>
        <source>not held: %1 is not confirmed to be a %2</source>
        <translation>nicht gehalten: %1 ist nicht als %2 bestätigt</translation>
    </message>
    <message>
        <location filename="../lib/bus/bus.cpp" line="+314"/>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location line="+32"/>
        <location line="+8"/>
        <source>read-only mode</source>
        <translation>Nur-Lese-Modus</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>the device&apos;s identity is not confirmed</source>
        <translation>die Identität des Geräts ist nicht bestätigt</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is not confirmed to be a %2 (it is checked again when it answers); set the hold again once it is</source>
        <translation>%1 ist nicht als %2 bestätigt (es wird erneut geprüft, sobald es antwortet); setzen Sie das Halten erneut, sobald es bestätigt ist</translation>
    </message>
    <message>
        <location line="+99"/>
        <source>exception %1, %2</source>
        <translation>Exception %1, %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>exception %1</source>
        <translation>Exception %1</translation>
    </message>
</context>
<context>
    <name>jumo::ClientEnd</name>
    <message>
        <location filename="../lib/sim/clientend.cpp" line="+54"/>
        <source>not a terminal</source>
        <translation>kein Terminal</translation>
    </message>
</context>
<context>
    <name>jumo::ClientTransport</name>
    <message>
        <location filename="../lib/bus/clienttransport.cpp" line="+45"/>
        <source>the line was closed</source>
        <translation>die Leitung wurde geschlossen</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>a request was sent while another was under way</source>
        <translation>eine Anfrage wurde gesendet, während eine andere noch lief</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not connected to %1</source>
        <translation>nicht verbunden mit %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>no reply within %1 ms</source>
        <translation>keine Antwort innerhalb von %1 ms</translation>
    </message>
</context>
<context>
    <name>jumo::CommandLineTool</name>
    <message>
        <location filename="../app/cli/commandlinetool.cpp" line="+27"/>
        <source>Usage: jumoctl COMMAND [options] [arguments]

Commissioning and monitoring of JUMO power and process controllers over Modbus RTU.

Commands on the register maps:
  families                 list the device families and their map files
  map FAMILY --csv|--json  print a family&apos;s register map
  plan FAMILY [ID...]      show the read requests for entries of a family
  decode FAMILY ID WORD... decode raw register words as an entry

The serial ports of this machine:
  ports [--json]           list them: stable by-id names, adapters, access
  find --port PATH [--from A --to B] [--baud LIST] [--format LIST]
                           find devices whose baud rate, format and address
                           nobody knows: every setting the families support

Stations of several lines:
  station FILE [--check|--json]
                           check a station file, list its lines and devices

Recorded values (no line is opened):
  history --station FILE|--db URL DEVICE ENTRY... [--from T --to T] [--csv|--json]
                           print what was recorded, with its validity

Commands on lines (all take --port PATH --baud N --format 8N1|8E1|8O1|8N2
--timeout MS --read-only --verbose for one line, or --line SPEC once per
line, or --station FILE); DEVICE is FAMILY@ADDRESS, e.g. ipc300@1, or
LINE/FAMILY@ADDRESS where there are several lines; its identity registers must
confirm FAMILY (exit code 4 if not; --no-identify skips it). A command of one
device opens only its line:
  scan [--from A --to B]   find devices and name their family, on every line
  read DEVICE ID...        read entries once
  write DEVICE ID=VALUE... write entries, verified by reading them back; a bit field&apos;s
                           ID=VALUE replaces every bit, ID.BIT=0|1 changes one bit only
  dump DEVICE [--json]     read every readable entry once
  monitor DEVICE... --jsonl|--csv [--interval MS] [--cycles N]
                           poll continuously, one record per poll cycle; the
                           devices of several lines at once
  backup DEVICE FILE       save every parameter of a device to a file
  diff DEVICE FILE         compare a device with a file (or FILE FILE)
  restore DEVICE FILE [--yes]
                           write what differs, each verified by read-back
  report DEVICE FILE       commissioning report as PDF (.pdf) or HTML

Exit codes: 0 done, 1 failed, 2 wrong arguments or files, 3 a write&apos;s outcome is
unknown, 4 another family at the address; 129, 130, 141 and 143 after SIGHUP,
SIGINT, a closed output (SIGPIPE) and SIGTERM, a command on lines then saying
on stderr what it got done.

&apos;jumoctl COMMAND --help&apos; describes a command.
</source>
        <translation>Aufruf: jumoctl COMMAND [Optionen] [Argumente]

Inbetriebnahme und Überwachung von JUMO-Leistungsstellern und Reglern über Modbus RTU.

Befehle auf den Registertabellen:
  families                 Gerätefamilien und ihre Map-Dateien auflisten
  map FAMILY --csv|--json  Registertabelle einer Familie ausgeben
  plan FAMILY [ID...]      Leseanfragen für Einträge einer Familie zeigen
  decode FAMILY ID WORD... Registerwörter als Eintrag dekodieren

Die seriellen Schnittstellen dieses Rechners:
  ports [--json]           auflisten: stabile by-id-Namen, Adapter, Zugriff
  find --port PATH [--from A --to B] [--baud LIST] [--format LIST]
                           Geräte suchen, deren Baudrate, Format und Adresse
                           niemand kennt: jede Einstellung, die die Familien kennen

Stationen mit mehreren Leitungen:
  station FILE [--check|--json]
                           Stationsdatei prüfen, ihre Leitungen und Geräte auflisten

Aufgezeichnete Werte (es wird keine Leitung geöffnet):
  history --station FILE|--db URL DEVICE ENTRY... [--from T --to T] [--csv|--json]
                           das Aufgezeichnete mit seiner Gültigkeit ausgeben

Befehle an Leitungen (alle mit --port PATH --baud N --format 8N1|8E1|8O1|8N2
--timeout MS --read-only --verbose für eine Leitung, oder --line SPEC je Leitung,
oder --station FILE); DEVICE ist FAMILY@ADDRESS, z. B. ipc300@1, oder
LINE/FAMILY@ADDRESS, wo es mehrere Leitungen gibt; seine Identitätsregister müssen
FAMILY bestätigen (sonst Exit-Code 4; --no-identify überspringt das). Ein Befehl
für ein Gerät öffnet nur dessen Leitung:
  scan [--from A --to B]   Geräte suchen und ihre Familie nennen, an jeder Leitung
  read DEVICE ID...        Einträge einmal lesen
  write DEVICE ID=VALUE... Einträge schreiben, durch Rücklesen geprüft; bei einem Bitfeld
                           ersetzt ID=VALUE jedes Bit, ID.BIT=0|1 ändert nur ein Bit
  dump DEVICE [--json]     alle lesbaren Einträge einmal lesen
  monitor DEVICE... --jsonl|--csv [--interval MS] [--cycles N]
                           fortlaufend abfragen, ein Datensatz je Abfragezyklus; die
                           Geräte mehrerer Leitungen gleichzeitig
  backup DEVICE FILE       alle Parameter eines Geräts in einer Datei sichern
  diff DEVICE FILE         ein Gerät mit einer Datei vergleichen (oder FILE FILE)
  restore DEVICE FILE [--yes]
                           Abweichendes schreiben, jeweils durch Rücklesen geprüft
  report DEVICE FILE       Inbetriebnahmebericht als PDF (.pdf) oder HTML

Exit-Codes: 0 erledigt, 1 fehlgeschlagen, 2 falsche Argumente oder Dateien, 3 Ausgang eines
Schreibvorgangs unbekannt, 4 eine andere Familie an der Adresse; 129, 130, 141 und 143 nach
SIGHUP, SIGINT, einer geschlossenen Ausgabe (SIGPIPE) und SIGTERM, wobei ein Befehl an
Leitungen auf stderr sagt, was er erledigt hat.

&apos;jumoctl COMMAND --help&apos; beschreibt einen Befehl.
</translation>
    </message>
    <message>
        <location line="+75"/>
        <source>jumoctl: the output could not be written: %1</source>
        <translation>jumoctl: die Ausgabe konnte nicht geschrieben werden: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>write failed</source>
        <translation>Schreiben fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>warning: refused map file: %1</source>
        <translation>Warnung: Map-Datei abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+22"/>
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
        <location line="+18"/>
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
    <name>jumo::CommissioningReport</name>
    <message>
        <location filename="../lib/commissioning/commissioningreport.cpp" line="+389"/>
        <source>(stale)</source>
        <translation>(veraltet)</translation>
    </message>
    <message>
        <location line="-204"/>
        <location line="+321"/>
        <source>Commissioning report</source>
        <translation>Inbetriebnahmebericht</translation>
    </message>
    <message>
        <location line="-362"/>
        <source>(empty)</source>
        <translation>(leer)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (stale)</source>
        <translation>%1 (veraltet)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>stale: not read in the last cycle</source>
        <translation>veraltet: im letzten Zyklus nicht gelesen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1; last known: %2</source>
        <translation>%1; zuletzt bekannt: %2</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Values without a unit are in a unit set on the device: %1.</source>
        <translation>Werte ohne Einheit sind in einer am Gerät eingestellten Einheit: %1.</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1, address %2, %3</source>
        <translation>%1, Adresse %2, %3</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>one of %1 (the device does not say which)</source>
        <translation>eines von %1 (das Gerät sagt nicht, welches)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 baud, %2</source>
        <translation>%1 Baud, %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>, port %1</source>
        <translation>, Schnittstelle %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Site</source>
        <translation>Standort</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+235"/>
        <source>Date</source>
        <translation>Datum</translation>
    </message>
    <message>
        <location line="-234"/>
        <source>Cabinet</source>
        <translation>Schaltschrank</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Engineer</source>
        <translation>Inbetriebnehmer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device tag</source>
        <translation>Kennzeichen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Line</source>
        <translation>Leitung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Software</source>
        <translation>Software</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>Identity</source>
        <translation>Identität</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The family has no identity registers.</source>
        <translation>Die Gerätefamilie hat keine Identitätsregister.</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>The family has no parameters.</source>
        <translation>Die Gerätefamilie hat keine Parameter.</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+2"/>
        <location line="+151"/>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="-153"/>
        <source>Default</source>
        <translation>Standardwert</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Default: the factory setting, or the value after power on, where the manual gives one; %1 marks a value that differs from it. Differing: %2 of %3 compared.</source>
        <translation>Standardwert: die Werkseinstellung oder der Wert nach dem Einschalten, wo das Handbuch einen nennt; %1 kennzeichnet einen davon abweichenden Wert. Abweichend: %2 von %3 verglichenen.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The manual gives no default values for these parameters: none are compared.</source>
        <translation>Das Handbuch nennt für diese Parameter keine Standardwerte: Es wird keiner verglichen.</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>The family has no live values.</source>
        <translation>Die Gerätefamilie hat keine Live-Werte.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>%1, bit %2</source>
        <translation>%1, Bit %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Active alarms and warnings</source>
        <translation>Aktive Alarme und Warnungen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Unknown: %1 could not be read; their alarms are not known.</source>
        <translation>Unbekannt: %1 konnte nicht gelesen werden; deren Alarme sind nicht bekannt.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>None active.</source>
        <translation>Keiner aktiv.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>None of the others active.</source>
        <translation>Von den übrigen keiner aktiv.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Where</source>
        <translation>Wo</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 on</source>
        <translation>%1 ein</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 off</source>
        <translation>%1 aus</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Writes since %1</source>
        <translation>Schreibvorgänge seit %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Writes</source>
        <translation>Schreibvorgänge</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>None.</source>
        <translation>Keine.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>confirmed by read-back</source>
        <translation>durch Rücklesen bestätigt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>accepted (cannot be read back)</source>
        <translation>angenommen (nicht rücklesbar)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read back another value</source>
        <translation>anderer Wert zurückgelesen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>refused by the device</source>
        <translation>vom Gerät abgelehnt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown: the answer was lost</source>
        <translation>unbekannt: die Antwort ging verloren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not verified</source>
        <translation>nicht überprüft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not sent</source>
        <translation>nicht gesendet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not sent: read-only mode</source>
        <translation>nicht gesendet: Nur-Lese-Modus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not sent: invalid value</source>
        <translation>nicht gesendet: ungültiger Wert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>identity not checked</source>
        <translation>Identität nicht geprüft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>broadcast acknowledged</source>
        <translation>Broadcast bestätigt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Outcome</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Signatures</source>
        <translation>Unterschriften</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device was commissioned with the parameters above.</source>
        <translation>Das Gerät wurde mit den obigen Parametern in Betrieb genommen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Commissioning engineer</source>
        <translation>Inbetriebnehmer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Customer</source>
        <translation>Kunde</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+4"/>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Signature</source>
        <translation>Unterschrift</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Commissioning report %1</source>
        <translation>Inbetriebnahmebericht %1</translation>
    </message>
    <message>
        <location line="-146"/>
        <source>Signal</source>
        <translation>Signal</translation>
    </message>
    <message>
        <location line="-51"/>
        <location line="+2"/>
        <location line="+49"/>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location line="-59"/>
        <location line="+30"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Live values</source>
        <translation>Live-Werte</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>As read at %1; a value with nothing under State is current. A value that could not be read shows %2 and why.</source>
        <translation>Gelesen am %1; ein Wert ohne Eintrag unter Zustand ist aktuell. Ein Wert, der nicht gelesen werden konnte, zeigt %2 und den Grund.</translation>
    </message>
    <message>
        <location line="+108"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Old value</source>
        <translation>Alter Wert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New value</source>
        <translation>Neuer Wert</translation>
    </message>
</context>
<context>
    <name>jumo::ConnectionBar</name>
    <message>
        <location filename="../ui/connectionbar.cpp" line="+20"/>
        <source>L&amp;ine:</source>
        <translation>Le&amp;itung:</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+142"/>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <location line="-127"/>
        <source>/dev/ttyUSB0 or tcp://HOST</source>
        <translation>/dev/ttyUSB0 oder tcp://HOST</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The line: a serial port (listed, or a typed path);
tcp://HOST[:PORT] for a Modbus TCP gateway (port 502 by default,
the device address is the unit id);
rtu+tcp://HOST:PORT for RTU frames through a serial device server.
Behind a gateway, baud and format are those of its serial side.</source>
        <translation>Die Leitung: eine serielle Schnittstelle (aufgelistet oder als Pfad eingegeben);
tcp://HOST[:PORT] für ein Modbus-TCP-Gateway (Port 502, wenn keiner angegeben ist,
die Geräteadresse ist die Unit-ID);
rtu+tcp://HOST:PORT für RTU-Telegramme über einen seriellen Geräteserver.
Hinter einem Gateway gelten Baudrate und Format seiner seriellen Seite.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Refresh</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>List the serial ports again</source>
        <translation>Serielle Schnittstellen erneut auflisten</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&amp;Port:</source>
        <translation>&amp;Port:</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Baud:</source>
        <translation>&amp;Baud:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Fo&amp;rmat:</source>
        <translation>Fo&amp;rmat:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Port: %1</source>
        <translation>Schnittstelle: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device now: %1</source>
        <translation>Gerätedatei jetzt: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Manufacturer: %1</source>
        <translation>Hersteller: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Serial number: %1</source>
        <translation>Seriennummer: %1</translation>
    </message>
    <message>
        <location line="+53"/>
        <source>Disconnect</source>
        <translation>Trennen</translation>
    </message>
</context>
<context>
    <name>jumo::ControlRow</name>
    <message>
        <location filename="../ui/controlrow.cpp" line="+60"/>
        <source>Precondition: %1</source>
        <translation>Voraussetzung: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stored in EEPROM: about 10,000 write cycles, write only when needed.</source>
        <translation>Im EEPROM gespeichert: etwa 10.000 Schreibzyklen, nur bei Bedarf schreiben.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stored in RAM: lost when the device is switched off.</source>
        <translation>Im RAM gespeichert: geht beim Ausschalten des Geräts verloren.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>send the command &quot;%1&quot;</source>
        <translation>den Befehl &quot;%1&quot; senden</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Write</source>
        <translation>Schreiben</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Write all bits</source>
        <translation>Alle Bits schreiben</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Back to the device&apos;s own value</source>
        <translation>Zurück zum geräteeigenen Wert</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the device&apos;s own value</source>
        <translation>der eigene Wert des Geräts</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hand %1 back to the device</source>
        <translation>die Vorgabe für %1 aufheben</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Pending: %1</source>
        <translation>Ausstehend: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Confirmed: %1</source>
        <translation>Bestätigt: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Refused: %1</source>
        <translation>Abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Unknown, check the device: %1</source>
        <translation>Unbekannt, bitte am Gerät prüfen: %1</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Write-only: the lamps show the states the device reports elsewhere.</source>
        <translation>Nur schreibbar: Die Lampen zeigen die Zustände, die das Gerät an anderer Stelle meldet.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Write-only: the device cannot report it.</source>
        <translation>Nur schreibbar: Das Gerät kann den Wert nicht melden.</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+9"/>
        <location line="+102"/>
        <source>Device: %1</source>
        <translation>Gerät: %1</translation>
    </message>
    <message>
        <location line="-39"/>
        <source>every bit off</source>
        <translation>alle Bits aus</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>on: %1</source>
        <translation>ein: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;%1&apos; is no number that can be read one way only; write it without thousands separators</source>
        <translation>„%1“ ist keine eindeutig lesbare Zahl; bitte ohne Tausenderpunkte schreiben</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>write %1 = %2</source>
        <translation>%1 = %2 schreiben</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>Do you want to %1?</source>
        <translation>Möchten Sie %1?</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This changes what the device drives.</source>
        <translation>Das ändert, was das Gerät ansteuert.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The value is stored in EEPROM, which lasts about 10,000 writes.</source>
        <translation>Der Wert wird im EEPROM gespeichert, das etwa 10.000 Schreibvorgänge verträgt.</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>switch &quot;%1&quot; on</source>
        <translation>„%1“ einschalten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>switch &quot;%1&quot; off</source>
        <translation>„%1“ ausschalten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 on</source>
        <translation>%1 ein</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 off</source>
        <translation>%1 aus</translation>
    </message>
    <message>
        <location line="-121"/>
        <source>Read-only mode: nothing is written to the devices.</source>
        <translation>Nur-Lese-Modus: Es wird nichts auf die Geräte geschrieben.</translation>
    </message>
    <message>
        <location line="+90"/>
        <source>Confirm write</source>
        <translation>Schreiben bestätigen</translation>
    </message>
    <message>
        <location line="-21"/>
        <source>Not written: %1</source>
        <translation>Nicht geschrieben: %1</translation>
    </message>
</context>
<context>
    <name>jumo::ControlsPanel</name>
    <message>
        <location filename="../ui/controlspanel.cpp" line="+57"/>
        <source>Setpoints</source>
        <translation>Sollwerte</translation>
    </message>
</context>
<context>
    <name>jumo::DataLogger</name>
    <message>
        <location filename="../lib/logs/datalogger.cpp" line="+26"/>
        <source>choose at least one value, an interval of at least 100 ms and files of at least 1 KiB</source>
        <translation>mindestens einen Wert, ein Intervall von mindestens 100 ms und Dateien von mindestens 1 KiB wählen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cannot create the folder %1</source>
        <translation>der Ordner %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <location line="+36"/>
        <location line="+15"/>
        <location line="+21"/>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>jumo::DataLoggingDialog</name>
    <message>
        <location filename="../ui/dataloggingdialog.cpp" line="+23"/>
        <source>Data logging</source>
        <translation>Datenaufzeichnung</translation>
    </message>
    <message>
        <location line="+15"/>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> MiB</source>
        <translation> MiB</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source> newest files</source>
        <translation> neueste Dateien</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Stopped: %1</source>
        <translation>Angehalten: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Interval:</source>
        <translation>Intervall:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New file after:</source>
        <translation>Neue Datei nach:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keep:</source>
        <translation>Behalten:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Folder:</source>
        <translation>Ordner:</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Values to log (a new file also starts each day):</source>
        <translation>Aufzuzeichnende Werte (jeden Tag beginnt auch eine neue Datei):</translation>
    </message>
    <message numerus="yes">
        <location line="+13"/>
        <source>Stopped; %n row(s) written.</source>
        <translation>
            <numerusform>Angehalten; %n Zeile geschrieben.</numerusform>
            <numerusform>Angehalten; %n Zeilen geschrieben.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Not started: %1</source>
        <translation>Nicht gestartet: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Logging to %1</source>
        <translation>Aufzeichnung nach %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Stop logging</source>
        <translation>Aufzeichnung beenden</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Start logging</source>
        <translation>Aufzeichnung starten</translation>
    </message>
</context>
<context>
    <name>jumo::DemoLine</name>
    <message>
        <location filename="../lib/sim/demoline.cpp" line="+20"/>
        <source>the simulated line ended (socat stopped)</source>
        <translation>die simulierte Leitung ist beendet (socat wurde gestoppt)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the simulator cannot open %1: %2</source>
        <translation>der Simulator kann %1 nicht öffnen: %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>no temporary folder for the demo line</source>
        <translation>kein temporärer Ordner für die Demo-Leitung</translation>
    </message>
</context>
<context>
    <name>jumo::DevicePage</name>
    <message>
        <location filename="../ui/devicepage.cpp" line="+41"/>
        <source>Read-only mode: values are shown, nothing is written to the device.</source>
        <translation>Nur-Lese-Modus: Werte werden angezeigt, es wird nichts auf das Gerät geschrieben.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Live values</source>
        <translation>Live-Werte</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+2"/>
        <source>Alarms and status</source>
        <translation>Alarme und Status</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Alarms and status (%1)</source>
        <translation>Alarme und Status (%1)</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>Controls</source>
        <translation>Bedienung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Program</source>
        <translation>Programm</translation>
    </message>
    <message>
        <location line="-30"/>
        <source>Trend</source>
        <translation>Trend</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>Wrong device: %1. Its values are not shown and nothing is written to it until the device at this address is of the family it was added as.</source>
        <translation>Falsches Gerät: %1. Seine Werte werden nicht angezeigt und nichts wird geschrieben, bis das Gerät an dieser Adresse zu der Familie gehört, als die es hinzugefügt wurde.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Checking that the device at this address is of this family.</source>
        <translation>Es wird geprüft, ob das Gerät an dieser Adresse zu dieser Familie gehört.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Identity not confirmed: %1</source>
        <translation>Identität nicht bestätigt: %1</translation>
    </message>
</context>
<context>
    <name>jumo::DeviceTile</name>
    <message>
        <location filename="../ui/devicetile.cpp" line="+161"/>
        <location line="+140"/>
        <location line="+126"/>
        <location line="+226"/>
        <source>(stale)</source>
        <translation>(veraltet)</translation>
    </message>
    <message>
        <location line="-469"/>
        <source>Bar: %1 to %2 %3</source>
        <translation>Balken: %1 bis %2 %3</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Bar: 0 to %1 (nominal)</source>
        <translation>Balken: 0 bis %1 (Nennwert)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bar: 0 to %1 (limit set on the device)</source>
        <translation>Balken: 0 bis %1 (am Gerät eingestellter Grenzwert)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No bar: its scale, %1, is not above zero.</source>
        <translation>Kein Balken: Die Skala, %1, ist nicht größer als null.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No bar: %1, a part of its scale, is not above zero.</source>
        <translation>Kein Balken: %1, ein Teil der Skala, ist nicht größer als null.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No bar: the device reports %1, which the map gives no number.</source>
        <translation>Kein Balken: Das Gerät meldet %1, wofür die Registertabelle keine Zahl nennt.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No bar: its scale is not known yet.</source>
        <translation>Kein Balken: Die Skala ist noch nicht bekannt.</translation>
    </message>
    <message>
        <location line="+89"/>
        <location line="+11"/>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>segment %1 of %2</source>
        <translation>Segment %1 von %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 left</source>
        <translation>noch %1</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>(beyond the scale)</source>
        <translation>(außerhalb der Skala)</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+410"/>
        <source>Mode: %1</source>
        <translation>Betriebsart: %1</translation>
    </message>
    <message>
        <location line="-408"/>
        <location line="+413"/>
        <source>Program: %1</source>
        <translation>Programm: %1</translation>
    </message>
    <message>
        <location line="-397"/>
        <source>Wrong device</source>
        <translation>Falsches Gerät</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Line lost</source>
        <translation>Leitung verloren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not answering</source>
        <translation>Antwortet nicht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Alarm</source>
        <translation>Alarm</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Warning</source>
        <translation>Warnung</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Normal</source>
        <translation>Normal</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Checking</source>
        <translation>Prüfung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Online</source>
        <translation>Online</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not answering since %1</source>
        <translation>Antwortet nicht seit %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Line lost since %1</source>
        <translation>Leitung verloren seit %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Line disconnected</source>
        <translation>Leitung getrennt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Checking identity</source>
        <translation>Identität wird geprüft</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Wrong device since %1</source>
        <translation>Falsches Gerät seit %1</translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source>%n active alarm(s)</source>
        <translation>
            <numerusform>%n aktiver Alarm</numerusform>
            <numerusform>%n aktive Alarme</numerusform>
        </translation>
    </message>
    <message>
        <location line="-59"/>
        <location line="+59"/>
        <source>Alarms unknown</source>
        <translation>Alarme unbekannt</translation>
    </message>
</context>
<context>
    <name>jumo::DeviceTitle</name>
    <message>
        <location filename="../lib/models/devicetitle.cpp" line="+7"/>
        <source>%1 @ %2</source>
        <translation>%1 @ %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 at address %2</source>
        <translation>%1 an Adresse %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 at address %2 on line %3</source>
        <translation>%1 an Adresse %2 an Leitung %3</translation>
    </message>
</context>
<context>
    <name>jumo::EventLog</name>
    <message>
        <location filename="../lib/logs/eventlog.cpp" line="+119"/>
        <source>no folder for the logs: neither JUMO_LOG_DIR, XDG_DATA_HOME nor HOME is set to an absolute folder</source>
        <translation>kein Ordner für die Protokolle: weder JUMO_LOG_DIR, XDG_DATA_HOME noch HOME ist auf einen absoluten Ordner gesetzt</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <location line="+66"/>
        <source>the file is replaced again and again</source>
        <translation>die Datei wird immer wieder ersetzt</translation>
    </message>
    <message>
        <location line="-76"/>
        <location line="+76"/>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>jumo::EventLogModel</name>
    <message>
        <location filename="../lib/models/eventlogmodel.cpp" line="+73"/>
        <source>unreadable record at byte %1 of %2</source>
        <translation>unlesbarer Eintrag bei Byte %1 von %2</translation>
    </message>
</context>
<context>
    <name>jumo::EventLogReader</name>
    <message>
        <location filename="../lib/logs/eventlogreader.cpp" line="+17"/>
        <source>cannot read %1</source>
        <translation>%1 kann nicht gelesen werden</translation>
    </message>
</context>
<context>
    <name>jumo::EventLogScanner</name>
    <message>
        <location filename="../lib/logs/eventlogscanner.cpp" line="+36"/>
        <source>cannot read %1</source>
        <translation>%1 kann nicht gelesen werden</translation>
    </message>
    <message numerus="yes">
        <location line="+136"/>
        <source>%n record(s) exported to %1</source>
        <translation>
            <numerusform>%n Eintrag nach %1 exportiert</numerusform>
            <numerusform>%n Einträge nach %1 exportiert</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>jumo::EventLogView</name>
    <message>
        <location filename="../ui/eventlogview.cpp" line="+39"/>
        <source>Filter: device, entry, kind, text...</source>
        <translation>Filter: Gerät, Eintrag, Art, Text...</translation>
    </message>
    <message>
        <location line="-9"/>
        <source>Export CSV...</source>
        <translation>CSV exportieren...</translation>
    </message>
    <message>
        <location line="+19"/>
        <location line="+13"/>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Exporting to %1...</source>
        <translation>Export nach %1...</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>Kept in %1</source>
        <translation>Gespeichert in %1</translation>
    </message>
    <message numerus="yes">
        <location line="+25"/>
        <source>%n record(s)</source>
        <translation>
            <numerusform>%n Eintrag</numerusform>
            <numerusform>%n Einträge</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n record(s) shown, reading older ones...</source>
        <translation>
            <numerusform>%n Eintrag angezeigt, ältere werden gelesen...</numerusform>
            <numerusform>%n Einträge angezeigt, ältere werden gelesen...</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>the newest %n record(s); scroll down for older ones</source>
        <translation>
            <numerusform>der neueste Eintrag; nach unten blättern für ältere</numerusform>
            <numerusform>die neuesten %n Einträge; nach unten blättern für ältere</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n matching record(s)</source>
        <translation>
            <numerusform>%n passender Eintrag</numerusform>
            <numerusform>%n passende Einträge</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n matching record(s) so far, searching...</source>
        <translation>
            <numerusform>bisher %n passender Eintrag, Suche läuft...</numerusform>
            <numerusform>bisher %n passende Einträge, Suche läuft...</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>the newest %n matching record(s); scroll down for older ones</source>
        <translation>
            <numerusform>der neueste passende Eintrag; nach unten blättern für ältere</numerusform>
            <numerusform>die neuesten %n passenden Einträge; nach unten blättern für ältere</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>jumo::FamilyRegistry</name>
    <message>
        <location filename="../lib/protocol/familyregistry.cpp" line="+58"/>
        <source>%1: family &apos;%2&apos; is defined by each of these files, so none of them is used</source>
        <translation>%1: die Familie &apos;%2&apos; ist in jeder dieser Dateien definiert, daher wird keine davon verwendet</translation>
    </message>
</context>
<context>
    <name>jumo::FileSaver</name>
    <message>
        <location filename="../lib/protocol/filesaver.cpp" line="+53"/>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <location line="-39"/>
        <source>not a regular file</source>
        <translation>keine reguläre Datei</translation>
    </message>
</context>
<context>
    <name>jumo::FindCommand</name>
    <message>
        <location filename="../app/cli/findcommand.cpp" line="+60"/>
        <source>Finds devices on a serial line whose settings nobody knows: tries every baud rate and data format the families support, first address 255 (where every IPC 300 and TYA 200 answers whatever its own address), then a quick scan of the address range, and says what answers where.</source>
        <translation>Sucht Geräte an einer seriellen Leitung, deren Einstellungen niemand kennt: probiert jede Baudrate und jedes Datenformat, das die Familien kennen, zuerst Adresse 255 (dort antwortet jeder IPC 300 und TYA 200, welche Adresse er auch hat), dann einen schnellen Scan des Adressbereichs, und sagt, was wo antwortet.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The serial port (its /dev/serial/by-id name, which &apos;jumoctl ports&apos; lists, or /dev/ttyUSB0, say).</source>
        <translation>Die serielle Schnittstelle (ihr /dev/serial/by-id-Name, den &apos;jumoctl ports&apos; auflistet, oder etwa /dev/ttyUSB0).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Try only these baud rates (a list: 9600,19200; default every rate a family supports).</source>
        <translation>Nur diese Baudraten probieren (eine Liste: 9600,19200; Standard: jede Rate, die eine Familie kennt).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rates</source>
        <translation>Raten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Try only these data formats (a list: 8N1,8E1; default every format a family supports).</source>
        <translation>Nur diese Datenformate probieren (eine Liste: 8N1,8E1; Standard: jedes Format, das eine Familie kennt).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>formats</source>
        <translation>Formate</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First address of the range (default 1).</source>
        <translation>Erste Adresse des Bereichs (Standard 1).</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+4"/>
        <source>address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <location line="-2"/>
        <source>Last address of the range (default 31, the most an RS-485 line carries).</source>
        <translation>Letzte Adresse des Bereichs (Standard 31, so viele trägt eine RS-485-Leitung höchstens).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Minimum response time the devices may be set to, in ms (default 0).</source>
        <translation>Mindestantwortzeit, auf die die Geräte eingestellt sein können, in ms (Standard 0).</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Show Qt&apos;s Modbus messages (CRC errors, timeouts, frames) on stderr.</source>
        <translation>Qts Modbus-Meldungen (CRC-Fehler, Zeitüberschreitungen, Telegramme) auf stderr zeigen.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>give the serial port: --port PATH (&apos;jumoctl ports&apos; lists them)</source>
        <translation>die serielle Schnittstelle angeben: --port PATH (&apos;jumoctl ports&apos; listet sie auf)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>find tries the baud rates and formats of a serial port; behind a gateway or a device server they are its own settings: set them there, then use &apos;jumoctl scan --port %1&apos;</source>
        <translation>find probiert die Baudraten und Formate einer seriellen Schnittstelle; hinter einem Gateway oder Geräteserver sind das dessen eigene Einstellungen: dort einstellen, dann &apos;jumoctl scan --port %1&apos; verwenden</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--from and --to must be addresses 1..255, from &lt;= to</source>
        <translation>--from und --to müssen Adressen 1..255 sein, from &lt;= to</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--baud takes rates the families know: 4800, 9600, 19200, 38400</source>
        <translation>--baud nimmt Raten, die die Familien kennen: 4800, 9600, 19200, 38400</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--format takes 8N1, 8E1, 8O1 and 8N2, not %1</source>
        <translation>--format nimmt 8N1, 8E1, 8O1 und 8N2, nicht %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--min-response must be 0..500 ms</source>
        <translation>--min-response muss 0..500 ms sein</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>no family supports these settings: %1 %2</source>
        <translation>keine Familie kennt diese Einstellungen: %1 %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>address 255 at %1 (%2 of %3)</source>
        <translation>Adresse 255 bei %1 (%2 von %3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2 of %3)</source>
        <translation>%1 (%2 von %3)</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%1: address %2, about %n s left</source>
        <translation>
            <numerusform>%1: Adresse %2, noch etwa %n s</numerusform>
            <numerusform>%1: Adresse %2, noch etwa %n s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>searching %n setting(s) (%1 baud; %2) for addresses %3..%4 and 255: about %5 s where nothing answers late</source>
        <translation>
            <numerusform>suche an %n Einstellung (%1 Baud; %2) nach den Adressen %3..%4 und 255: etwa %5 s, wo nichts spät antwortet</numerusform>
            <numerusform>suche an %n Einstellungen (%1 Baud; %2) nach den Adressen %3..%4 und 255: etwa %5 s, wo nichts spät antwortet</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source>the range is short, so up to %n address(es) next to it are probed once first at each setting, to hear late answers, and not reported</source>
        <translation>
            <numerusform>der Bereich ist kurz, daher wird bei jeder Einstellung bis zu %n Adresse daneben zuerst einmal abgefragt, um späte Antworten zu hören, und nicht gemeldet</numerusform>
            <numerusform>der Bereich ist kurz, daher werden bei jeder Einstellung bis zu %n Adressen daneben zuerst einmal abgefragt, um späte Antworten zu hören, und nicht gemeldet</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10"/>
        <source>trying %1</source>
        <translation>probiere %1</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>at %1: address %2 answers, but matches no known family</source>
        <translation>bei %1: Adresse %2 antwortet, passt aber zu keiner bekannten Familie</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>at %1: %2 at address %3 (%4)</source>
        <translation>bei %1: %2 an Adresse %3 (%4)</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>at %1: address %3 answers as %2, and no other address did: its own address is %3, or its answer there was lost (search again)</source>
        <translation>bei %1: Adresse %3 antwortet als %2, und keine andere Adresse: seine eigene Adresse ist %3, oder seine Antwort dort ging verloren (erneut suchen)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>at %1: address %3 answers as %2, as every %2 does whatever its own address; its own is outside %4..%5 (--from and --to look further)</source>
        <translation>bei %1: Adresse %3 antwortet als %2, wie jeder %2, welche Adresse er auch hat; seine eigene liegt außerhalb von %4..%5 (--from und --to suchen weiter)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 at address %2 answers at %3 baud in %4: the device or the adapter takes one for the other (a pseudo-terminal does not carry even parity; many UARTs take 8N2 for 8N1); its own is in its interface settings</source>
        <translation>%1 an Adresse %2 antwortet bei %3 Baud in %4: das Gerät oder der Adapter hält das eine für das andere (ein Pseudo-Terminal überträgt keine gerade Parität; viele UARTs nehmen 8N2 für 8N1); seine eigene Einstellung steht in seinen Schnittstelleneinstellungen</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>find: %1</source>
        <translation>find: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>the search stopped: %n device(s) found before, the settings after it not tried</source>
        <translation>
            <numerusform>die Suche endete: %n Gerät vorher gefunden, die Einstellungen danach nicht probiert</numerusform>
            <numerusform>die Suche endete: %n Geräte vorher gefunden, die Einstellungen danach nicht probiert</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>%n device(s) found before the search stopped</source>
        <translation>
            <numerusform>%n Gerät gefunden, bevor die Suche endete</numerusform>
            <numerusform>%n Geräte gefunden, bevor die Suche endete</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n device(s) found in %1 s</source>
        <translation>
            <numerusform>%n Gerät gefunden in %1 s</numerusform>
            <numerusform>%n Geräte gefunden in %1 s</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the devices answer at different baud rates: a line needs one, so set them alike</source>
        <translation>die Geräte antworten bei verschiedenen Baudraten: eine Leitung braucht eine, also alle gleich einstellen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the line&apos;s settings where the most answered: --baud %1 --format %2</source>
        <translation>die Einstellungen der Leitung, bei denen die meisten antworteten: --baud %1 --format %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>nothing answered: check the wiring (A/B swapped?), the termination and the adapter, or a minimum response time set in the devices (--min-response)</source>
        <translation>nichts hat geantwortet: Verdrahtung (A/B vertauscht?), Abschluss und Adapter prüfen, oder eine in den Geräten eingestellte Mindestantwortzeit (--min-response)</translation>
    </message>
</context>
<context>
    <name>jumo::FindDialog</name>
    <message>
        <location filename="../ui/finddialog.cpp" line="+31"/>
        <source>&amp;Search</source>
        <translation>&amp;Suchen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel search</source>
        <translation>Suche abbrechen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Find devices on an unknown line</source>
        <translation>Geräte an einer unbekannten Leitung finden</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>An RS-485 line carries at most 31 devices; they are most often given the first addresses.</source>
        <translation>Eine RS-485-Leitung trägt höchstens 31 Geräte; meist bekommen sie die ersten Adressen.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>not started</source>
        <translation>nicht gestartet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Answers at</source>
        <translation>Antwortet bei</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Address</source>
        <translation>Adresse</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(nothing answered yet)</source>
        <translation>(noch keine Antwort)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Addresses</source>
        <translation>Adressen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Port: %1. Every baud rate and data format the device families support is tried, address 255 first (every IPC 300 and TYA 200 answers there), then a quick scan of the addresses.</source>
        <translation>Schnittstelle: %1. Jede Baudrate und jedes Datenformat, das die Gerätefamilien kennen, wird probiert, zuerst Adresse 255 (dort antwortet jeder IPC 300 und TYA 200), dann ein schneller Scan der Adressen.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Line settings to use:</source>
        <translation>Einstellungen für die Leitung:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Use these settings and add the checked devices</source>
        <translation>Diese Einstellungen &amp;übernehmen und die markierten Geräte hinzufügen</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>address 255 at %1</source>
        <translation>Adresse 255 bei %1</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>%1, address %2: about %n s left</source>
        <translation>
            <numerusform>%1, Adresse %2: noch etwa %n s</numerusform>
            <numerusform>%1, Adresse %2: noch etwa %n s</numerusform>
        </translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 baud %2</source>
        <translation>%1 Baud %2</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n setting(s) to try: about %1 s where nothing answers late.</source>
        <translation>
            <numerusform>%n Einstellung zu probieren: etwa %1 s, wo nichts spät antwortet.</numerusform>
            <numerusform>%n Einstellungen zu probieren: etwa %1 s, wo nichts spät antwortet.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+47"/>
        <source>answers, but matches no known family</source>
        <translation>antwortet, passt aber zu keiner bekannten Familie</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>%1 answers here and at no other address: its own address is %2, or its answer there was lost (search again)</source>
        <translation>%1 antwortet hier und an keiner anderen Adresse: seine eigene Adresse ist %2, oder seine Antwort dort ging verloren (erneut suchen)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 answers here, as every one does; its own address is outside %2..%3</source>
        <translation>%1 antwortet hier, wie jeder; seine eigene Adresse liegt außerhalb von %2..%3</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>cancelled after %1 s</source>
        <translation>abgebrochen nach %1 s</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>stopped: %1</source>
        <translation>beendet: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>nothing answered (in %1 s): check the wiring, the termination and the adapter</source>
        <translation>nichts hat geantwortet (in %1 s): Verdrahtung, Abschluss und Adapter prüfen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>done in %1 s</source>
        <translation>fertig in %1 s</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1 at address %2</source>
        <translation>%1 an Adresse %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 answered at more than one data format of a baud rate: the device or the adapter takes one for the other (a pseudo-terminal does not carry even parity; many UARTs take 8N2 for 8N1). The device&apos;s own setting is in its interface menu.</source>
        <translation>%1 antwortete bei mehr als einem Datenformat einer Baudrate: das Gerät oder der Adapter hält das eine für das andere (ein Pseudo-Terminal überträgt keine gerade Parität; viele UARTs nehmen 8N2 für 8N1). Die eigene Einstellung des Geräts steht in seinem Schnittstellenmenü.</translation>
    </message>
</context>
<context>
    <name>jumo::HistoryCommands</name>
    <message>
        <location filename="../app/cli/historycommands.cpp" line="+115"/>
        <source>Prints the recorded values of a device&apos;s entries from FROM to TO with their state and validity: every sample kept, and one-minute rows (minimum, mean, maximum) where the samples are thinned out. Reads the station&apos;s history (--station FILE: its file in the log folder) or the database given by --db; no line is opened.</source>
        <translation>Gibt die aufgezeichneten Werte der Einträge eines Geräts von FROM bis TO mit Zustand und Gültigkeit aus: jeden aufbewahrten Messwert und Minutenzeilen (Minimum, Mittelwert, Maximum), wo die Messwerte ausgedünnt sind. Liest die Historie der Station (--station FILE: ihre Datei im Protokollordner) oder die mit --db angegebene Datenbank; es wird keine Leitung geöffnet.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The station file whose history is read.</source>
        <translation>Die Stationsdatei, deren Historie gelesen wird.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FILE</source>
        <translation>FILE</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The history: an SQLite file, or postgresql://[USER@]HOST[:PORT]/DATABASE (the password from JUMO_HISTORY_PASSWORD or ~/.pgpass).</source>
        <translation>Die Historie: eine SQLite-Datei oder postgresql://[USER@]HOST[:PORT]/DATABASE (das Passwort aus JUMO_HISTORY_PASSWORD oder ~/.pgpass).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>URL</source>
        <translation>URL</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+1"/>
        <source>TIME</source>
        <translation>TIME</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>End, as --from. Default: now.</source>
        <translation>Ende, wie --from. Standard: now.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV: time,device,entry,value,unit,state,validity,resolution,minimum,mean,maximum.</source>
        <translation>CSV: time,device,entry,value,unit,state,validity,resolution,minimum,mean,maximum.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>One JSON document: the device, the span and each entry&apos;s records.</source>
        <translation>Ein JSON-Dokument: das Gerät, die Zeitspanne und die Datensätze jedes Eintrags.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The device: FAMILY@ADDRESS, LINE/FAMILY@ADDRESS or STATION/LINE/FAMILY@ADDRESS.</source>
        <translation>Das Gerät: FAMILY@ADDRESS, LINE/FAMILY@ADDRESS oder STATION/LINE/FAMILY@ADDRESS.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Entries to print.</source>
        <translation>Auszugebende Einträge.</translation>
    </message>
    <message>
        <location line="-26"/>
        <location line="+30"/>
        <location line="+21"/>
        <location line="+2"/>
        <location line="+34"/>
        <source>jumoctl history: %1</source>
        <translation>jumoctl history: %1</translation>
    </message>
    <message>
        <location line="-112"/>
        <source>&apos;%1&apos; is no time</source>
        <translation>&apos;%1&apos; ist keine Zeit</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 does not exist in local time (%2): the clocks skip it; give it with its offset, such as %3, or in UTC, such as %4</source>
        <translation>%1 gibt es in Ortszeit (%2) nicht: die Uhren überspringen sie; mit Zeitzonenversatz angeben, etwa %3, oder in UTC, etwa %4</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 is twice in local time (%2), the clocks go back: taken as the first, %3; the second is %4</source>
        <translation>%1 gibt es in Ortszeit (%2) zweimal, die Uhren werden zurückgestellt: genommen wird die erste, %3; die zweite ist %4</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Start: an ISO 8601 time (local unless it names its offset), &apos;now&apos;, or a time before now such as -90s, -15m, -2h, -7d. Default: -1h. A local time the clocks skip is refused; of one they show twice, the first is taken.</source>
        <translation>Beginn: eine Zeit nach ISO 8601 (Ortszeit, wenn sie keinen Zeitzonenversatz nennt), &apos;now&apos; oder eine Zeit vor jetzt wie -90s, -15m, -2h, -7d. Vorgabe: -1h. Eine Ortszeit, die die Uhren überspringen, wird abgelehnt; von einer, die sie zweimal zeigen, wird die erste genommen.</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>give at most one of --csv and --json</source>
        <translation>höchstens eines von --csv und --json angeben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>give exactly one of --station FILE and --db URL</source>
        <translation>genau eines von --station FILE und --db URL angeben</translation>
    </message>
    <message numerus="yes">
        <location line="+170"/>
        <source>%n record(s) printed</source>
        <translation>
            <numerusform>%n Datensatz ausgegeben</numerusform>
            <numerusform>%n Datensätze ausgegeben</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>jumoctl history: %1: %n record(s) with a state this version does not know, shown as unknown_state (validity unknown)</source>
        <translation>
            <numerusform>jumoctl history: %1: %n Datensatz mit einem Zustand, den diese Version nicht kennt, gezeigt als unknown_state (Gültigkeit unbekannt)</numerusform>
            <numerusform>jumoctl history: %1: %n Datensätze mit einem Zustand, den diese Version nicht kennt, gezeigt als unknown_state (Gültigkeit unbekannt)</numerusform>
        </translation>
    </message>
    <message>
        <location line="-158"/>
        <source>--to must be after --from</source>
        <translation>--to muss nach --from liegen</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>jumoctl history: no log folder to find the history in: %1</source>
        <translation>jumoctl history: kein Protokollordner, in dem die Historie liegen könnte: %1</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>nothing was read (opening %1)</source>
        <translation>nichts gelesen (beim Öffnen von %1)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>jumoctl history: nothing of %1 is recorded in %2</source>
        <translation>jumoctl history: von %1 ist in %2 nichts aufgezeichnet</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>recorded devices: %1</source>
        <translation>aufgezeichnete Geräte: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 names several devices: %2</source>
        <translation>%1 bezeichnet mehrere Geräte: %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 is not recorded for %2 (recorded: %3)</source>
        <translation>%1 ist für %2 nicht aufgezeichnet (aufgezeichnet: %3)</translation>
    </message>
    <message>
        <location line="+57"/>
        <source>(minute: %1 to %2, mean %3)</source>
        <translation>(Minute: %1 bis %2, Mittelwert %3)</translation>
    </message>
</context>
<context>
    <name>jumo::HistoryDatabase</name>
    <message>
        <location filename="../lib/history/historydatabase.cpp" line="+102"/>
        <source>cannot open the history %1: Qt&apos;s %2 driver is not installed (%3)</source>
        <translation>die Historie %1 kann nicht geöffnet werden: Qts Treiber %2 ist nicht installiert (%3)</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>no history at %1</source>
        <translation>keine Historie unter %1</translation>
    </message>
    <message>
        <location line="+45"/>
        <location line="+11"/>
        <source>open</source>
        <translation>geöffnet</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>the history %1 changed while it was read (a recorder started on it): read it again</source>
        <translation>die Historie %1 hat sich beim Lesen geändert (ein Aufzeichner hat auf ihr begonnen): bitte erneut lesen</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+181"/>
        <source>%1 is damaged: %2</source>
        <translation>%1 ist beschädigt: %2</translation>
    </message>
    <message>
        <location line="-175"/>
        <source>unknown error</source>
        <translation>unbekannter Fehler</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>cannot %1 the history %2: %3</source>
        <extracomment>%1 is &quot;open&quot;, &quot;write&quot;, &quot;read&quot;; %2 the file or database; %3 the reason</extracomment>
        <translation>die Historie %2 kann nicht %1 werden: %3</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+21"/>
        <location line="+187"/>
        <source>write</source>
        <translation>geschrieben</translation>
    </message>
    <message>
        <location line="-168"/>
        <location line="+136"/>
        <source>cannot use the history %1: it was written by a newer version (schema %2, this one knows %3)</source>
        <translation>die Historie %1 ist nicht verwendbar: sie wurde von einer neueren Version geschrieben (Schema %2, diese kennt %3)</translation>
    </message>
    <message>
        <location line="-118"/>
        <source>%1 is not a JUMO history file: it is empty</source>
        <translation>%1 ist keine JUMO-Historiendatei: sie ist leer</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 is not a JUMO history file: it is not an SQLite database</source>
        <translation>%1 ist keine JUMO-Historiendatei: sie ist keine SQLite-Datenbank</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1 is damaged: its header names no page size (%2)</source>
        <translation>%1 ist beschädigt: ihr Kopf nennt keine Seitengröße (%2)</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>%1 is damaged: it ends inside a page (%2 bytes, pages of %3): it was cut off</source>
        <translation>%1 ist beschädigt: sie endet mitten in einer Seite (%2 Bytes, Seiten zu %3): sie wurde abgeschnitten</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 is damaged: it ends after %2 bytes, where its header says %3: it was cut off</source>
        <translation>%1 ist beschädigt: sie endet nach %2 Bytes, ihr Kopf sagt %3: sie wurde abgeschnitten</translation>
    </message>
    <message>
        <location line="+37"/>
        <source>no table %1</source>
        <translation>keine Tabelle %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the table %1 lacks the column(s) %2</source>
        <translation>der Tabelle %1 fehlen die Spalte(n) %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 holds no JUMO history: none of the history&apos;s tables is there</source>
        <translation>%1 enthält keine JUMO-Historie: keine der Tabellen der Historie ist da</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 is not a JUMO history file: an SQLite database without the history&apos;s tables</source>
        <translation>%1 ist keine JUMO-Historiendatei: eine SQLite-Datenbank ohne die Tabellen der Historie</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1 is damaged: it names no schema version</source>
        <translation>%1 ist beschädigt: sie nennt keine Schemaversion</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 is damaged: &apos;%2&apos; is no schema version</source>
        <translation>%1 ist beschädigt: &apos;%2&apos; ist keine Schemaversion</translation>
    </message>
    <message>
        <location line="-48"/>
        <location line="+39"/>
        <location line="+30"/>
        <source>read</source>
        <translation>gelesen</translation>
    </message>
</context>
<context>
    <name>jumo::HistoryLocation</name>
    <message>
        <location filename="../lib/history/historylocation.cpp" line="+37"/>
        <source>&apos;%1&apos; is no history database: %2 (use postgresql://[USER@]HOST[:PORT]/DATABASE or a file)</source>
        <translation>&apos;%1&apos; ist keine Historien-Datenbank: %2 (postgresql://[USER@]HOST[:PORT]/DATABASE oder eine Datei verwenden)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>empty</source>
        <translation>leer</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>unknown scheme &apos;%1&apos;</source>
        <translation>unbekanntes Schema &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a password in the address can be read by every user of this computer; use a password file or JUMO_HISTORY_PASSWORD</source>
        <translation>ein Passwort in der Adresse kann jeder Benutzer dieses Rechners lesen; verwenden Sie eine Passwortdatei oder JUMO_HISTORY_PASSWORD</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no host</source>
        <translation>kein Host</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>name one database: postgresql://HOST/DATABASE</source>
        <translation>eine Datenbank nennen: postgresql://HOST/DATABASE</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>an address has no query</source>
        <translation>eine Adresse hat keine Abfrage</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>port out of range</source>
        <translation>Port außerhalb des Bereichs</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>a user and a password are for a PostgreSQL database, not for the file %1</source>
        <translation>Benutzer und Passwort sind für eine PostgreSQL-Datenbank, nicht für die Datei %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>cannot read the password file %1</source>
        <translation>die Passwortdatei %1 ist nicht lesbar</translation>
    </message>
</context>
<context>
    <name>jumo::HistoryReader</name>
    <message>
        <location filename="../lib/history/historyreader.cpp" line="+77"/>
        <location line="+14"/>
        <location line="+20"/>
        <location line="+6"/>
        <location line="+19"/>
        <location line="+17"/>
        <location line="+21"/>
        <location line="+7"/>
        <location line="+16"/>
        <location line="+6"/>
        <source>read</source>
        <translation>gelesen</translation>
    </message>
</context>
<context>
    <name>jumo::HistoryWriter</name>
    <message>
        <location filename="../lib/history/historywriter.cpp" line="+105"/>
        <location line="+6"/>
        <location line="+38"/>
        <location line="+37"/>
        <location line="+41"/>
        <location line="+6"/>
        <location line="+102"/>
        <location line="+21"/>
        <location line="+4"/>
        <location line="+24"/>
        <location line="+14"/>
        <location line="+3"/>
        <location line="+4"/>
        <source>write</source>
        <translation>geschrieben</translation>
    </message>
    <message>
        <location line="-201"/>
        <location line="+94"/>
        <location line="+20"/>
        <source>read</source>
        <translation>gelesen</translation>
    </message>
    <message>
        <location line="+100"/>
        <location line="+38"/>
        <source>History not recorded: %1</source>
        <translation>Historie nicht aufgezeichnet: %1</translation>
    </message>
    <message numerus="yes">
        <location line="-12"/>
        <source>History recorded again (%n sample(s) since the failure not recorded)</source>
        <translation>
            <numerusform>Historie wird wieder aufgezeichnet (%n Messwert seit dem Fehler nicht aufgezeichnet)</numerusform>
            <numerusform>Historie wird wieder aufgezeichnet (%n Messwerte seit dem Fehler nicht aufgezeichnet)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>jumo::IdentityCheck</name>
    <message>
        <location filename="../lib/bus/identitycheck.cpp" line="+68"/>
        <source>%1: confirmed</source>
        <translation>%1: bestätigt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 refused: the device at address %2 is a %3 (%4), not a %5</source>
        <translation>%1 abgelehnt: das Gerät an Adresse %2 ist ein %3 (%4), kein %5</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 refused: the device at address %2 answers, but its identity registers match no known family, so it is no %3</source>
        <translation>%1 abgelehnt: das Gerät an Adresse %2 antwortet, aber seine Identitätsregister passen zu keiner bekannten Familie, es ist also kein %3</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1: no answer at address %2, so its family cannot be confirmed</source>
        <translation>%1: keine Antwort an Adresse %2, die Familie kann nicht bestätigt werden</translation>
    </message>
</context>
<context>
    <name>jumo::IdentityGate</name>
    <message>
        <location filename="../app/cli/identitygate.cpp" line="+22"/>
        <source>Trust the named family without checking the device&apos;s identity registers (for devices whose identity cannot be read; the audit log records it).</source>
        <translation>Der genannten Familie vertrauen, ohne die Identitätsregister des Geräts zu prüfen (für Geräte, deren Identität nicht lesbar ist; das Audit-Protokoll vermerkt es).</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the family was not checked against the device (--no-identify)</source>
        <translation>die Familie wurde nicht am Gerät geprüft (--no-identify)</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>nothing was read or written; --no-identify skips the check for a device whose identity registers cannot be read</source>
        <translation>nichts wurde gelesen oder geschrieben; --no-identify überspringt die Prüfung bei einem Gerät, dessen Identitätsregister nicht lesbar sind</translation>
    </message>
</context>
<context>
    <name>jumo::IdentityPanel</name>
    <message>
        <location filename="../ui/identitypanel.cpp" line="+44"/>
        <source>address %1</source>
        <translation>Adresse %1</translation>
    </message>
</context>
<context>
    <name>jumo::LedGrid</name>
    <message numerus="yes">
        <location filename="../ui/ledgrid.cpp" line="+87"/>
        <source>%n active alarm(s)</source>
        <translation>
            <numerusform>%n aktiver Alarm</numerusform>
            <numerusform>%n aktive Alarme</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Alarms unknown: the device cannot be read</source>
        <translation>Alarme unbekannt: Das Gerät kann nicht gelesen werden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>(stale: not read in the device&apos;s last cycle)</source>
        <translation>(veraltet: im letzten Zyklus des Geräts nicht gelesen)</translation>
    </message>
</context>
<context>
    <name>jumo::LineAddress</name>
    <message>
        <location filename="../lib/bus/lineaddress.cpp" line="+23"/>
        <source>no line address: give a serial port, tcp://HOST[:PORT] or rtu+tcp://HOST:PORT</source>
        <translation>keine Leitungsadresse: geben Sie eine serielle Schnittstelle, tcp://HOST[:PORT] oder rtu+tcp://HOST:PORT an</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>unknown line address scheme &apos;%1://&apos; in &apos;%2&apos;: use tcp://HOST[:PORT] (Modbus TCP) or rtu+tcp://HOST:PORT (RTU over TCP)</source>
        <translation>unbekanntes Schema &apos;%1://&apos; der Leitungsadresse &apos;%2&apos;: verwenden Sie tcp://HOST[:PORT] (Modbus TCP) oder rtu+tcp://HOST:PORT (RTU über TCP)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;%1&apos; has &apos;%2&apos; after the port: a line address is only HOST and PORT</source>
        <translation>&apos;%1&apos; hat &apos;%2&apos; nach dem Port: eine Leitungsadresse besteht nur aus HOST und PORT</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos;: user names are not part of a line address</source>
        <translation>&apos;%1&apos;: Benutzernamen gehören nicht in eine Leitungsadresse</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;%1&apos;: an IPv6 address in brackets lacks its &apos;]&apos;</source>
        <translation>&apos;%1&apos;: einer IPv6-Adresse in Klammern fehlt ihre &apos;]&apos;</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos;: after &apos;]&apos; only &apos;:PORT&apos; may follow</source>
        <translation>&apos;%1&apos;: nach &apos;]&apos; darf nur &apos;:PORT&apos; folgen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;%1&apos;: write an IPv6 address in brackets, e.g. tcp://[::1]:502</source>
        <translation>&apos;%1&apos;: schreiben Sie eine IPv6-Adresse in Klammern, z. B. tcp://[::1]:502</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;%1&apos; names no host</source>
        <translation>&apos;%1&apos; nennt keinen Host</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos;: &apos;%2&apos; is not a host name or address</source>
        <translation>&apos;%1&apos;: &apos;%2&apos; ist kein Hostname und keine Adresse</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos; names no port: a serial device server has no standard port, give rtu+tcp://HOST:PORT</source>
        <translation>&apos;%1&apos; nennt keinen Port: ein serieller Geräteserver hat keinen Standardport, geben Sie rtu+tcp://HOST:PORT an</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;%1&apos; has &apos;:&apos; but no port after it</source>
        <translation>&apos;%1&apos; hat &apos;:&apos;, aber keinen Port danach</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos;: the port must be a number 1..65535, not &apos;%2&apos;</source>
        <translation>&apos;%1&apos;: der Port muss eine Zahl von 1 bis 65535 sein, nicht &apos;%2&apos;</translation>
    </message>
</context>
<context>
    <name>jumo::LineCommands</name>
    <message>
        <location filename="../app/cli/linecommands.cpp" line="+112"/>
        <source>the audit log did not take a record: %1</source>
        <translation>das Audit-Protokoll hat einen Eintrag nicht aufgenommen: %1</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>spec</source>
        <translation>Angabe</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Station file (JSON) with the lines, their settings and devices.</source>
        <translation>Stationsdatei (JSON) mit den Leitungen, ihren Einstellungen und Geräten.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>file</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location line="+4"/>
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
        <location line="+818"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location line="-818"/>
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
        <location line="+818"/>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <location line="-815"/>
        <source>Never write to any line (control-room mode; the system configuration can set it for everyone, a station file for one line).</source>
        <translation>Auf keine Leitung schreiben (Leitwarten-Modus; die Systemkonfiguration kann ihn für alle festlegen, eine Stationsdatei für eine Leitung).</translation>
    </message>
    <message>
        <location line="+13"/>
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
        <location line="+14"/>
        <source>give the lines one way: --port, --line or --station</source>
        <translation>die Leitungen auf eine Art angeben: --port, --line oder --station</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--%1 does not go with --station: the station file sets each line&apos;s own</source>
        <translation>--%1 passt nicht zu --station: die Stationsdatei legt das für jede Leitung selbst fest</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1: the station has no lines</source>
        <translation>%1: die Station hat keine Leitungen</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>give the line: --port PATH, --line SPEC (once per line) or --station FILE</source>
        <translation>die Leitung angeben: --port PATH, --line SPEC (je Leitung einmal) oder --station FILE</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>line %1: %2</source>
        <translation>Leitung %1: %2</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>&apos;%1&apos; is not a device: use FAMILY@ADDRESS, e.g. ipc300@1 (families: %2)</source>
        <translation>&apos;%1&apos; ist kein Gerät: FAMILY@ADDRESS verwenden, z. B. ipc300@1 (Gerätefamilien: %2)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>device address %1 is outside 1..255</source>
        <translation>Geräteadresse %1 liegt außerhalb von 1..255</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>a %1 cannot have address %2: its addresses are %3..%4</source>
        <translation>ein %1 kann nicht Adresse %2 haben: seine Adressen sind %3..%4</translation>
    </message>
    <message numerus="yes">
        <location line="+46"/>
        <source>%n device(s) found before the scan stopped</source>
        <translation>
            <numerusform>%n Gerät gefunden, bevor die Suche endete</numerusform>
            <numerusform>%n Geräte gefunden, bevor die Suche endete</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>%n poll cycle(s) printed</source>
        <translation>
            <numerusform>%n Abfragezyklus ausgegeben</numerusform>
            <numerusform>%n Abfragezyklen ausgegeben</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+18"/>
        <source>nothing was written</source>
        <translation>nichts wurde geschrieben</translation>
    </message>
    <message numerus="yes">
        <location line="-15"/>
        <source>%1 of %n write(s) done</source>
        <translation>
            <numerusform>%1 von %n Schreibvorgang erledigt</numerusform>
            <numerusform>%1 von %n Schreibvorgängen erledigt</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source> (%n restored and verified)</source>
        <translation>
            <numerusform> (%n wiederhergestellt und geprüft)</numerusform>
            <numerusform> (%n wiederhergestellt und geprüft)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>; %1 was being written: its outcome is unknown, check the device</source>
        <translation>; %1 wurde gerade geschrieben: das Ergebnis ist unbekannt, bitte am Gerät prüfen</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>; %n not written</source>
        <translation>
            <numerusform>; %n nicht geschrieben</numerusform>
            <numerusform>; %n nicht geschrieben</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no backup saved</source>
        <translation>keine Sicherung gespeichert</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no report written</source>
        <translation>kein Bericht geschrieben</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>First address (default 1).</source>
        <translation>Erste Adresse (Standard 1).</translation>
    </message>
    <message>
        <location line="-374"/>
        <location line="+374"/>
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
        <location line="+2"/>
        <source>Probe every address at the full timeout (the slowest family&apos;s worst case), twice where silent. Slow; the default quick scan probes again at the full timeout wherever it heard anything.</source>
        <translation>Jede Adresse mit der vollen Zeitüberschreitung abfragen (dem ungünstigsten Fall der langsamsten Familie), zweimal, wo sie still bleibt. Langsam; die voreingestellte schnelle Suche fragt überall dort erneut mit der vollen Zeitüberschreitung ab, wo sie etwas gehört hat.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--from and --to must be addresses 1..255, from &lt;= to</source>
        <translation>--from und --to müssen Adressen 1..255 sein, from &lt;= to</translation>
    </message>
    <message numerus="yes">
        <location line="+16"/>
        <source>address %1 (%2 of %3), about %n s left</source>
        <translation>
            <numerusform>Adresse %1 (%2 von %3), noch etwa %n s</numerusform>
            <numerusform>Adresse %1 (%2 von %3), noch etwa %n s</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>address %1 answers as %2, which every %2 does whatever its own address: not listed</source>
        <translation>Adresse %1 antwortet als %2, wie es jeder %2 unabhängig von seiner eigenen Adresse tut: nicht aufgeführt</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>address %1 answers, but matches no known family</source>
        <translation>Adresse %1 antwortet, passt aber zu keiner bekannten Gerätefamilie</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>quick scan of addresses %1..%2: each probed once at %3 ms, again at the full %4 ms where anything was heard (--thorough probes every address at the full timeout)</source>
        <translation>schnelle Suche der Adressen %1..%2: jede einmal mit %3 ms abgefragt, erneut mit den vollen %4 ms, wo etwas gehört wurde (--thorough fragt jede Adresse mit der vollen Zeitüberschreitung ab)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>as asked</source>
        <translation>wie verlangt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a Modbus TCP gateway answers every request itself, at its own timeout</source>
        <translation>ein Modbus-TCP-Gateway beantwortet jede Anfrage selbst, nach seiner eigenen Zeitüberschreitung</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>thorough scan of addresses %1..%2 (%3): a silent address costs two probes at %4 ms, each followed by as long a quiet time; up to %n s</source>
        <translation>
            <numerusform>gründliche Suche der Adressen %1..%2 (%3): eine stille Adresse kostet zwei Abfragen mit %4 ms, nach jeder eine ebenso lange Ruhezeit; bis zu %n s</numerusform>
            <numerusform>gründliche Suche der Adressen %1..%2 (%3): eine stille Adresse kostet zwei Abfragen mit %4 ms, nach jeder eine ebenso lange Ruhezeit; bis zu %n s</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+32"/>
        <source>%n device(s) found in %1 s</source>
        <translation>
            <numerusform>%n Gerät in %1 s gefunden</numerusform>
            <numerusform>%n Geräte in %1 s gefunden</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n address(es) probed again at the full timeout</source>
        <translation>
            <numerusform>%n Adresse erneut mit der vollen Zeitüberschreitung abgefragt</numerusform>
            <numerusform>%n Adressen erneut mit der vollen Zeitüberschreitung abgefragt</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>%n device(s) found</source>
        <translation>
            <numerusform>%n Gerät gefunden</numerusform>
            <numerusform>%n Geräte gefunden</numerusform>
        </translation>
    </message>
    <message>
        <location line="+32"/>
        <source>exception %1: %2</source>
        <translation>Exception %1: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not available on this device (exception 2)</source>
        <translation>auf diesem Gerät nicht vorhanden (Exception 2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no answer</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <location line="+13"/>
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
        <location line="+4"/>
        <source>Entry ids.</source>
        <translation>Kennungen der Einträge.</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>&apos;%1&apos; is not an entry of %2</source>
        <translation>&apos;%1&apos; ist kein Eintrag von %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;%1&apos; is write-only</source>
        <translation>&apos;%1&apos; ist nur schreibbar</translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+17"/>
        <source>some entries could not be read</source>
        <translation>einige Einträge konnten nicht gelesen werden</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>For a broadcast (FAMILY@0): the addresses to read it back from, e.g. 1,2,5.</source>
        <translation>Bei einem Broadcast (FAMILY@0): die Adressen, von denen zurückgelesen wird, z. B. 1,2,5.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>addresses</source>
        <translation>Adressen</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>&apos;%1&apos; is not a device: use FAMILY@ADDRESS</source>
        <translation>&apos;%1&apos; ist kein Gerät: FAMILY@ADDRESS verwenden</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>--verify takes addresses 1..255, not &apos;%1&apos;</source>
        <translation>--verify erwartet Adressen 1..255, nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+129"/>
        <source>the line %1 is read-only (station file): nothing is written to the devices</source>
        <translation>die Leitung %1 ist schreibgeschützt (Stationsdatei): es wird nichts auf die Geräte geschrieben</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>FAMILY@ADDRESS; LINE/FAMILY@ADDRESS where there are several lines (default with --station: every device of the station file).</source>
        <translation>FAMILY@ADDRESS; LINE/FAMILY@ADDRESS, wo es mehrere Leitungen gibt (Vorgabe mit --station: jedes Gerät der Stationsdatei).</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>jumoctl monitor: name at least one device (or give a station file that lists them)</source>
        <translation>jumoctl monitor: mindestens ein Gerät nennen (oder eine Stationsdatei angeben, die Geräte auflistet)</translation>
    </message>
    <message>
        <location line="+221"/>
        <source>Compares a device with a parameter file, or two files.

Exit code (as diff(1)): 0 nothing differs; 1 something does; 2 a
problem: a file that cannot be read or compared (another family,
unknown ids, invalid values, another software version), a device
that does not answer; 4 another family at the address.</source>
        <translation>Vergleicht ein Gerät mit einer Parameterdatei oder zwei Dateien miteinander.

Exit-Code (wie bei diff(1)): 0 nichts weicht ab; 1 etwas weicht ab; 2 ein
Problem: eine Datei, die nicht gelesen oder verglichen werden kann (andere Familie,
unbekannte IDs, ungültige Werte, andere Softwareversion), ein Gerät,
das nicht antwortet; 4 eine andere Familie an der Adresse.</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>FAMILY@ADDRESS (LINE/FAMILY@ADDRESS where there are several lines), or a first parameter file.</source>
        <translation>FAMILY@ADDRESS (LINE/FAMILY@ADDRESS, wo es mehrere Leitungen gibt) oder eine erste Parameterdatei.</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>cannot read %1</source>
        <translation>%1 kann nicht gelesen werden</translation>
    </message>
    <message>
        <location line="+150"/>
        <source>Writes the commissioning report of a device, a document to sign: a title block (site, cabinet, tag, engineer, date, device, line), identity, parameters with the manual&apos;s defaults, live values, active alarms, today&apos;s writes and signature lines. FILE ending in .pdf gives PDF (A4, numbered pages), else HTML.</source>
        <translation>Schreibt den Inbetriebnahmebericht eines Geräts, ein Dokument zum Unterschreiben: Kopfdaten (Standort, Schaltschrank, Kennzeichen, Inbetriebnehmer, Datum, Gerät, Leitung), Identität, Parameter mit den Standardwerten des Handbuchs, Live-Werte, aktive Alarme, die heutigen Schreibvorgänge und Unterschriftszeilen. Endet DATEI auf .pdf, entsteht PDF (A4, nummerierte Seiten), sonst HTML.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Site for the report&apos;s title block (the plant, the hall).</source>
        <translation>Standort für die Kopfdaten des Berichts (die Anlage, die Halle).</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>text</source>
        <translation>Text</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Cabinet or panel the device is in.</source>
        <translation>Schaltschrank oder Tafel, in dem das Gerät sitzt.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device&apos;s tag in the plant, e.g. TIC-101.</source>
        <translation>Kennzeichen des Geräts in der Anlage, z. B. TIC-101.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Name of the commissioning engineer.</source>
        <translation>Name des Inbetriebnehmers.</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <location line="-1252"/>
        <source>Show Qt&apos;s Modbus messages (CRC errors, timeouts, frames) on stderr.</source>
        <translation>Die Modbus-Meldungen von Qt (CRC-Fehler, Zeitüberschreitungen, Telegramme) auf stderr ausgeben.</translation>
    </message>
    <message>
        <location line="-31"/>
        <source>The one line: a serial port (its /dev/serial/by-id name, which &apos;jumoctl ports&apos; lists, or /dev/ttyUSB0, say), tcp://HOST[:PORT] for a Modbus TCP gateway (port 502 by default; the device address is the unit id) or rtu+tcp://HOST:PORT for raw RTU through a serial device server.</source>
        <translation>Die eine Leitung: eine serielle Schnittstelle (ihr Name unter /dev/serial/by-id, den &apos;jumoctl ports&apos; auflistet, oder etwa /dev/ttyUSB0), tcp://HOST[:PORT] für ein Modbus-TCP-Gateway (Port 502, wenn keiner angegeben ist; die Geräteadresse ist die Unit-ID) oder rtu+tcp://HOST:PORT für reines RTU über einen seriellen Geräteserver.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>A line, given once per line: its ADDRESS, then as needed ,name=NAME ,baud=N ,format=8N1 ,timeout=MS ,min-response=MS ,retries=N ,read-only, e.g. /dev/ttyUSB0,name=a,baud=19200. Unnamed lines are line1, line2, ... The options below are the defaults of every --line.</source>
        <translation>Eine Leitung, je Leitung einmal angegeben: ihre ADDRESS, dann nach Bedarf ,name=NAME ,baud=N ,format=8N1 ,timeout=MS ,min-response=MS ,retries=N ,read-only, z. B. /dev/ttyUSB0,name=a,baud=19200. Leitungen ohne Namen heißen line1, line2, ... Die folgenden Optionen sind die Vorgaben jeder --line.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Baud rate: 4800, 9600, 19200 or 38400 (default 9600); behind a gateway, its serial side&apos;s (it sets the timing).</source>
        <translation>Baudrate: 4800, 9600, 19200 oder 38400 (Standard 9600); hinter einem Gateway die seiner seriellen Seite (sie bestimmt das Zeitverhalten).</translation>
    </message>
    <message>
        <location line="+361"/>
        <source>Finds devices on the line and names their family; with several lines (--line, --station), on every line at once.</source>
        <translation>Sucht Geräte an der Leitung und benennt ihre Gerätefamilie; bei mehreren Leitungen (--line, --station) an allen Leitungen gleichzeitig.</translation>
    </message>
    <message numerus="yes">
        <location line="+81"/>
        <source>the range is short, so %n address(es) outside it (%1) are probed once first, to hear late answers; what answers there is not reported</source>
        <translation>
            <numerusform>der Bereich ist kurz, daher wird %n Adresse außerhalb (%1) zuerst einmal abgefragt, um späte Antworten zu hören; was dort antwortet, wird nicht gemeldet</numerusform>
            <numerusform>der Bereich ist kurz, daher werden %n Adressen außerhalb (%1) zuerst einmal abgefragt, um späte Antworten zu hören; was dort antwortet, wird nicht gemeldet</numerusform>
        </translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the range is too short to listen for late answers after a quick pass, and the timeout too long to borrow listeners for it</source>
        <translation>der Bereich ist zu kurz, um nach einem schnellen Durchgang auf späte Antworten zu hören, und die Zeitüberschreitung zu lang, um dafür Nachbaradressen zu borgen</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>scanning %1</source>
        <translation>Suche %1</translation>
    </message>
    <message>
        <location line="+87"/>
        <location line="+542"/>
        <location line="+172"/>
        <source>FAMILY@ADDRESS, e.g. ipc300@1; LINE/FAMILY@ADDRESS where there are several lines.</source>
        <translation>FAMILY@ADDRESS, z. B. ipc300@1; LINE/FAMILY@ADDRESS, wo es mehrere Leitungen gibt.</translation>
    </message>
    <message>
        <location line="-647"/>
        <source>Writes entries of a device; each write is verified by reading it back.

ID=VALUE writes the whole entry: for a bit field it replaces EVERY bit of
the word. ID.BIT=0|1 (or on|off, true|false) changes that bit only and keeps
the others as the device reports them, read just before the write; bits of
one entry given together go out in one write.

Exit code: 0 every write confirmed (or acknowledged, where nothing reads it
back); 1 a write failed (refused by the device, read back different, not
sent, read-only mode); 3 the outcome of a write is unknown or unverified
(its answer was lost; a command is never sent twice): check the device;
2 wrong arguments, nothing sent.</source>
        <translation>Schreibt Einträge eines Geräts; jeder Schreibvorgang wird durch Rücklesen überprüft.

ID=VALUE schreibt den ganzen Eintrag: bei einem Bitfeld ersetzt das JEDES Bit
des Worts. ID.BIT=0|1 (oder on|off, true|false) ändert nur dieses Bit und
behält die anderen so, wie das Gerät sie meldet, unmittelbar vor dem Schreiben
gelesen; zusammen angegebene Bits eines Eintrags gehen in einem Schreibvorgang.

Exit-Code: 0 jeder Schreibvorgang bestätigt (oder quittiert, wo nichts
zurückgelesen werden kann); 1 ein Schreibvorgang ist gescheitert (vom Gerät
abgelehnt, anders zurückgelesen, nicht gesendet, Nur-Lese-Modus); 3 der
Ausgang eines Schreibvorgangs ist unbekannt oder ungeprüft (die Antwort ging
verloren; ein Befehl wird nie zweimal gesendet): Gerät prüfen;
2 falsche Argumente, nichts gesendet.</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>FAMILY@ADDRESS, or FAMILY@0 for a broadcast; LINE/ before it where there are several lines.</source>
        <translation>FAMILY@ADDRESS oder FAMILY@0 für einen Broadcast; LINE/ davor, wo es mehrere Leitungen gibt.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>ID=VALUE, e.g. input_setpoint=42.5, or ID.BIT=0|1, e.g. binary_signal_write.digital_output=1.</source>
        <translation>ID=VALUE, z. B. input_setpoint=42.5, oder ID.BIT=0|1, z. B. binary_signal_write.digital_output=1.</translation>
    </message>
    <message>
        <location line="+114"/>
        <source>unknown, check the device: </source>
        <translation>unbekannt, Gerät prüfen: </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>unverified: </source>
        <translation>ungeprüft: </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>(was %1)</source>
        <translation>(vorher %1)</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1; writes are kept in the audit log, so nothing is written</source>
        <translation>%1; Schreibvorgänge werden im Audit-Log festgehalten, deshalb wird nichts geschrieben</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>read-only mode is set by the system configuration (%1): nothing is written to the devices</source>
        <translation>Der Nur-Lese-Modus ist durch die Systemkonfiguration festgelegt (%1): Es wird nichts auf die Geräte geschrieben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>read-only mode (--read-only): nothing is written to the devices</source>
        <translation>Nur-Lese-Modus (--read-only): Es wird nichts auf die Geräte geschrieben</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Polls devices continuously and prints every poll cycle; devices of several lines are polled at once, each line on its own.

A device that does not answer does not stop the others: its records say so
(condition offline), and its family is checked whenever it answers (again);
until then it has no values. Devices never confirmed are named at the end.

Exit code: 0 every value read; 1 a value could not be read, a line was lost,
or a device was never confirmed; 4 another family answered at a device&apos;s
address and it was never confirmed; 129, 130, 141, 143 after a signal.</source>
        <translation>Fragt Geräte fortlaufend ab und gibt jeden Abfragezyklus aus; Geräte mehrerer Leitungen werden gleichzeitig abgefragt, jede Leitung für sich.

Ein Gerät, das nicht antwortet, hält die anderen nicht auf: seine Datensätze sagen es
(Zustand offline), und seine Familie wird geprüft, sobald es (wieder) antwortet;
bis dahin hat es keine Werte. Nie bestätigte Geräte werden am Ende genannt.

Exit-Code: 0 jeder Wert gelesen; 1 ein Wert konnte nicht gelesen werden, eine Leitung ging
verloren oder ein Gerät wurde nie bestätigt; 4 an der Adresse eines Geräts antwortete eine
andere Familie und es wurde nie bestätigt; 129, 130, 141, 143 nach einem Signal.</translation>
    </message>
    <message>
        <location line="+11"/>
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
        <location line="+10"/>
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
        <location line="+22"/>
        <source>&apos;%1&apos; is not a readable entry of %2</source>
        <translation>&apos;%1&apos; ist kein lesbarer Eintrag von %2</translation>
    </message>
    <message>
        <location line="+140"/>
        <source>never confirmed: %1 did not answer</source>
        <translation>nie bestätigt: %1 hat nicht geantwortet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>never confirmed: %1</source>
        <translation>nie bestätigt: %1</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>no differences</source>
        <translation>keine Unterschiede</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n parameter(s) differ (%1 -&gt; %2):</source>
        <translation>
            <numerusform>%n Parameter weicht ab (%1 -&gt; %2):</numerusform>
            <numerusform>%n Parameter weichen ab (%1 -&gt; %2):</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+1"/>
        <source>(missing)</source>
        <translation>(fehlt)</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Saves every parameter of a device to a file.</source>
        <translation>Sichert alle Parameter eines Geräts in einer Datei.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Writes the parameters of a file that differ from the device, each verified by read-back.</source>
        <translation>Schreibt die Parameter einer Datei, die vom Gerät abweichen, jeweils durch Rücklesen geprüft.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Write without asking.</source>
        <translation>Ohne Rückfrage schreiben.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Parameter file (JSON).</source>
        <translation>Parameterdatei (JSON).</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>the files are for different or unknown families: %1, %2</source>
        <translation>die Dateien gehören zu verschiedenen oder unbekannten Gerätefamilien: %1, %2</translation>
    </message>
    <message>
        <location line="+31"/>
        <location line="+40"/>
        <source>refused: %1</source>
        <translation>abgelehnt: %1</translation>
    </message>
    <message>
        <location line="-35"/>
        <source>read-only mode: nothing would be restored</source>
        <translation>Nur-Lese-Modus: es würde nichts wiederhergestellt</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>these parameters could not be read, nothing was done: %1</source>
        <translation>diese Parameter konnten nicht gelesen werden, es wurde nichts getan: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+13"/>
        <source>%n parameter(s) of %1 saved to %2</source>
        <translation>
            <numerusform>%n Parameter von %1 in %2 gesichert</numerusform>
            <numerusform>%n Parameter von %1 in %2 gesichert</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+20"/>
        <source>%n parameter(s) missing from the file are left as they are.</source>
        <translation>
            <numerusform>%n Parameter, der in der Datei fehlt, bleibt unverändert.</numerusform>
            <numerusform>%n Parameter, die in der Datei fehlen, bleiben unverändert.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+12"/>
        <source>Write %n parameter(s) to the device? [y/N] </source>
        <translation>
            <numerusform>%n Parameter auf das Gerät schreiben? [j/N] </numerusform>
            <numerusform>%n Parameter auf das Gerät schreiben? [j/N] </numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>y</source>
        <translation>j</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>nothing written</source>
        <translation>nichts geschrieben</translation>
    </message>
    <message>
        <location line="+45"/>
        <source>Report file (.pdf or .html).</source>
        <translation>Berichtsdatei (.pdf oder .html).</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1 did not answer: no report written</source>
        <translation>%1 hat nicht geantwortet: kein Bericht geschrieben</translation>
    </message>
    <message>
        <location line="+9"/>
        <location line="+16"/>
        <source>no report written: its writes of today are unknown: %1</source>
        <translation>kein Bericht geschrieben: die Schreibvorgänge von heute sind unbekannt: %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Commissioning report of %1</source>
        <translation>Inbetriebnahmebericht von %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>report of %1 written to %2</source>
        <translation>Bericht von %1 in %2 geschrieben</translation>
    </message>
    <message numerus="yes">
        <location line="+19"/>
        <source>%n parameter(s) restored and verified</source>
        <translation>
            <numerusform>%n Parameter wiederhergestellt und geprüft</numerusform>
            <numerusform>%n Parameter wiederhergestellt und geprüft</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>jumo::LineConnection</name>
    <message>
        <location filename="../lib/bus/lineconnection.cpp" line="+93"/>
        <source>cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message>
        <location line="+44"/>
        <location line="+6"/>
        <location filename="../ui/stationline.cpp" line="+79"/>
        <source>line lost: %1</source>
        <translation>Leitung verloren: %1</translation>
    </message>
</context>
<context>
    <name>jumo::LineDialog</name>
    <message>
        <location filename="../ui/linedialog.cpp" line="+30"/>
        <source>/dev/ttyUSB0, tcp://10.0.0.20:502 or rtu+tcp://10.0.0.21:4001</source>
        <translation>/dev/ttyUSB0, tcp://10.0.0.20:502 oder rtu+tcp://10.0.0.21:4001</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>&amp;Name:</source>
        <translation>&amp;Name:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Address:</source>
        <translation>&amp;Adresse:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Baud:</source>
        <translation>&amp;Baud:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Format:</source>
        <translation>&amp;Format:</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>A line needs a name.</source>
        <translation>Eine Leitung braucht einen Namen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A line&apos;s name has 1 to 32 letters (A-Z, a-z), digits, &apos;_&apos;, &apos;.&apos; or &apos;-&apos;.</source>
        <translation>Der Name einer Leitung hat 1 bis 32 Buchstaben (A-Z, a-z), Ziffern, &apos;_&apos;, &apos;.&apos; oder &apos;-&apos;.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>There is a line named %1 already.</source>
        <translation>Es gibt schon eine Leitung namens %1.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Choose or type the line&apos;s address.</source>
        <translation>Adresse der Leitung wählen oder eingeben.</translation>
    </message>
</context>
<context>
    <name>jumo::LineHeader</name>
    <message>
        <location filename="../ui/lineheader.cpp" line="+28"/>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>%1, devices: %2</source>
        <translation>%1, Geräte: %2</translation>
    </message>
</context>
<context>
    <name>jumo::LiveValuesModel</name>
    <message>
        <location filename="../lib/models/livevaluesmodel.cpp" line="+141"/>
        <source>Value: %1</source>
        <translation>Wert: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1, register %2, %3</source>
        <translation>%1, Register %2, %3</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Status: %1</source>
        <translation>Status: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Last known value: %1, %2 s ago</source>
        <translation>Letzter bekannter Wert: %1, vor %2 s</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Section</source>
        <translation>Abschnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Signal</source>
        <translation>Signal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Age</source>
        <translation>Alter</translation>
    </message>
</context>
<context>
    <name>jumo::MainWindow</name>
    <message>
        <location filename="../ui/mainwindow.cpp" line="+91"/>
        <location line="+4"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location line="-4"/>
        <location line="+4"/>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>Register</source>
        <translation>Register</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bit</source>
        <translation>Bit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Id</source>
        <translation>Kennung</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Signal</source>
        <translation>Signal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Entry</source>
        <translation>Eintrag</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Old value</source>
        <translation>Alter Wert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New value</source>
        <translation>Neuer Wert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Message</source>
        <translation>Meldung</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>JUMO HMI [read-only]</source>
        <translation>JUMO HMI [Nur-Lese-Modus]</translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1198"/>
        <source>JUMO HMI</source>
        <translation>JUMO HMI</translation>
    </message>
    <message>
        <location line="-1196"/>
        <source>Connection</source>
        <translation>Verbindung</translation>
    </message>
    <message>
        <location line="+156"/>
        <source>&amp;Line</source>
        <translation>&amp;Leitung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Connect</source>
        <translation>&amp;Verbinden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Disconnect</source>
        <translation>&amp;Trennen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Connect &amp;all lines</source>
        <translation>&amp;Alle Leitungen verbinden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Disc&amp;onnect all lines</source>
        <translation>A&amp;lle Leitungen trennen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;New line...</source>
        <translation>&amp;Neue Leitung...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Edit the line...</source>
        <translation>Leitung &amp;bearbeiten...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Remove the line...</source>
        <translation>Leitung &amp;entfernen...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Add a device...</source>
        <translation>Gerät &amp;hinzufügen...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Find on an unknown line...</source>
        <translation>An unbekannter Leitung &amp;finden...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Remove the shown device...</source>
        <translation>Angezeigtes Gerät &amp;entfernen...</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>&amp;Commissioning report of the shown device...</source>
        <translation>Inbetriebnahme&amp;bericht des angezeigten Geräts...</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>commissioning-report-%1-%2.pdf</source>
        <translation>inbetriebnahmebericht-%1-%2.pdf</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>La&amp;nguage</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>&amp;Overview</source>
        <translation>&amp;Übersicht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Traffic and statistics</source>
        <translation>Daten&amp;verkehr und Statistik</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Alarm &amp;journal</source>
        <translation>Alarm&amp;journal</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Write audit log</source>
        <translation>&amp;Schreibprotokoll</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Device pages</source>
        <translation>&amp;Geräteseiten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device %1 in the list</source>
        <translation>Gerät %1 der Liste</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Next page</source>
        <translation>&amp;Nächste Seite</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Previous page</source>
        <translation>V&amp;orige Seite</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Previous t&amp;ab of the device page</source>
        <translation>Vorig&amp;er Reiter der Geräteseite</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Go to the page &amp;list</source>
        <translation>Zur Seiten&amp;liste</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>T&amp;heme</source>
        <translation>&amp;Farbschema</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&amp;Compact overview</source>
        <translation>&amp;Kompakte Übersicht</translation>
    </message>
    <message>
        <location line="+65"/>
        <location line="+219"/>
        <location line="+34"/>
        <source>Connect</source>
        <translation>Verbinden</translation>
    </message>
    <message>
        <location line="-652"/>
        <source>Overview</source>
        <translation>Übersicht</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Traffic and statistics</source>
        <translation>Datenverkehr und Statistik</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Alarm journal</source>
        <translation>Alarmjournal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write audit log</source>
        <translation>Schreibprotokoll</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Add...</source>
        <translation>Hinzufügen...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scan...</source>
        <translation>Suchen...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove</source>
        <translation>Entfernen</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>READ-ONLY</source>
        <translation>NUR LESEN</translation>
    </message>
    <message>
        <location line="+317"/>
        <source>Address %1 on line %2 is taken by %3: a line has one device per address.</source>
        <translation>Adresse %1 an Leitung %2 ist durch %3 belegt: eine Leitung hat ein Gerät je Adresse.</translation>
    </message>
    <message>
        <location line="+202"/>
        <source>Choose or type the line&apos;s address first: a serial port, tcp://HOST[:PORT] or rtu+tcp://HOST:PORT.</source>
        <translation>Wählen Sie zuerst die Adresse der Leitung oder geben Sie sie ein: eine serielle Schnittstelle, tcp://HOST[:PORT] oder rtu+tcp://HOST:PORT.</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>no address</source>
        <translation>keine Adresse</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Not connected:
%1</source>
        <translation>Nicht verbunden:
%1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>New line</source>
        <translation>Neue Leitung</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Edit line</source>
        <translation>Leitung bearbeiten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Disconnect line %1 first.</source>
        <translation>Zuerst Leitung %1 trennen.</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Edit line %1</source>
        <translation>Leitung %1 bearbeiten</translation>
    </message>
    <message>
        <location line="+15"/>
        <location line="+13"/>
        <source>Remove line</source>
        <translation>Leitung entfernen</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>%1 is the only line; change its address with Edit instead.</source>
        <translation>%1 ist die einzige Leitung; ihre Adresse lässt sich stattdessen mit Bearbeiten ändern.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Remove line %1 from the station?</source>
        <translation>Leitung %1 aus der Station entfernen?</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Devices removed with it: %1 (%2).</source>
        <translation>Mit ihr entfernte Geräte: %1 (%2).</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>%1 connected</source>
        <translation>%1 verbunden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 lost</source>
        <translation>%1 verloren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 disconnected</source>
        <translation>%1 getrennt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lines: %1</source>
        <translation>Leitungen: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+66"/>
        <source>no values read: %n line(s) lost (%1)</source>
        <translation>
            <numerusform>keine Werte gelesen: %n Leitung verloren (%1)</numerusform>
            <numerusform>keine Werte gelesen: %n Leitungen verloren (%1)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no values read: the line is lost</source>
        <translation>keine Werte gelesen: die Leitung ist verloren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>last error: %1</source>
        <translation>letzter Fehler: %1</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>%1 on line %2</source>
        <translation>%1 an Leitung %2</translation>
    </message>
    <message>
        <location line="+129"/>
        <source>Remove device</source>
        <translation>Gerät entfernen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove %1 from this window?</source>
        <translation>%1 aus diesem Fenster entfernen?</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>It is no longer polled; its page, trend and data logging close. Nothing is written to the device.</source>
        <translation>Es wird nicht mehr abgefragt; seine Seite, sein Trend und seine Datenaufzeichnung werden geschlossen. Auf das Gerät wird nichts geschrieben.</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Connect line %1 first, or choose a connected line.</source>
        <translation>Zuerst Leitung %1 verbinden oder eine verbundene Leitung wählen.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Scan line %1</source>
        <translation>Leitung %1 durchsuchen</translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+4"/>
        <location line="+8"/>
        <source>Find devices</source>
        <translation>Geräte finden</translation>
    </message>
    <message>
        <location line="-12"/>
        <source>Choose the line&apos;s serial port first.</source>
        <translation>Zuerst die serielle Schnittstelle der Leitung wählen.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Line %1 is reached through a gateway or a device server, whose serial settings are its own: set them there, then scan the line.</source>
        <translation>Leitung %1 wird über ein Gateway oder einen Geräteserver erreicht, dessen serielle Einstellungen seine eigenen sind: dort einstellen, dann die Leitung scannen.</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>The search needs the port of line %1 for itself and tries other settings on it: disconnect the line now? Its devices are not polled while the search runs.</source>
        <translation>Die Suche braucht die Schnittstelle von Leitung %1 für sich und probiert andere Einstellungen darauf: die Leitung jetzt trennen? Solange die Suche läuft, werden ihre Geräte nicht abgefragt.</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Find devices on line %1</source>
        <translation>Geräte an Leitung %1 finden</translation>
    </message>
    <message>
        <location line="+97"/>
        <source>Data logging of %1 stopped: %2</source>
        <translation>Datenaufzeichnung von %1 angehalten: %2</translation>
    </message>
    <message>
        <location line="-736"/>
        <source>address %1: %2</source>
        <translation>Adresse %1: %2</translation>
    </message>
    <message>
        <location line="-326"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>&amp;Devices</source>
        <translation>&amp;Geräte</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Scan the line...</source>
        <translation>Leitung durch&amp;suchen...</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&amp;Parameters: back up, compare, restore...</source>
        <translation>&amp;Parameter: sichern, vergleichen, wiederherstellen...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&amp;Data logging of the shown device...</source>
        <translation>&amp;Datenaufzeichnung des angezeigten Geräts...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Data logging</source>
        <translation>Datenaufzeichnung</translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+24"/>
        <source>Report</source>
        <translation>Bericht</translation>
    </message>
    <message>
        <location line="-45"/>
        <location line="+10"/>
        <location line="+11"/>
        <source>Open the page of a device first.</source>
        <translation>Zuerst die Seite eines Geräts öffnen.</translation>
    </message>
    <message numerus="yes">
        <location line="-118"/>
        <source>Not logged (%n record(s) so far): %1</source>
        <translation>
            <numerusform>Nicht protokolliert (bisher %n Eintrag): %1</numerusform>
            <numerusform>Nicht protokolliert (bisher %n Einträge): %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+138"/>
        <source>Commissioning report</source>
        <translation>Inbetriebnahmebericht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDF (*.pdf);;HTML (*.html)</source>
        <translation>PDF (*.pdf);;HTML (*.html)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The language changes when the HMI is started again.</source>
        <translation>Die Sprache wird beim nächsten Start der HMI umgestellt.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About</source>
        <translation>Ü&amp;ber</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>About JUMO HMI</source>
        <translation>Über JUMO HMI</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>JUMO HMI %1
Commissioning and monitoring of JUMO power and process controllers over Modbus RTU.</source>
        <translation>JUMO HMI %1
Inbetriebnahme und Überwachung von JUMO-Leistungs- und Prozessreglern über Modbus RTU.</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Ne&amp;xt tab of the device page</source>
        <translation>Nächster &amp;Reiter der Geräteseite</translation>
    </message>
    <message>
        <location line="+106"/>
        <source>Add device</source>
        <translation>Gerät hinzufügen</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Demo line failed: %1</source>
        <translation>Demo-Leitung fehlgeschlagen: %1</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Starting the simulated demo line...</source>
        <translation>Simulierte Demo-Leitung wird gestartet...</translation>
    </message>
    <message>
        <location line="+351"/>
        <source>Connected to %1</source>
        <translation>Verbunden mit %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Line lost, waiting for the port to come back...</source>
        <translation>Leitung verloren, warte, bis die Schnittstelle wieder verfügbar ist...</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Line: %1</source>
        <translation>Leitung: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 requests/s</source>
        <translation>%1 Anfragen/s</translation>
    </message>
    <message numerus="yes">
        <location line="+23"/>
        <source>%n error(s); last: %1</source>
        <translation>
            <numerusform>%n Fehler; zuletzt: %1</numerusform>
            <numerusform>%n Fehler; zuletzt: %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no errors</source>
        <translation>keine Fehler</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the family is not checked against the device (--no-identify)</source>
        <translation>die Familie wird nicht am Gerät geprüft (--no-identify)</translation>
    </message>
    <message>
        <location line="+206"/>
        <source>Scan</source>
        <translation>Suchen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Connect to a line first.</source>
        <translation>Zuerst mit einer Leitung verbinden.</translation>
    </message>
    <message>
        <location line="+126"/>
        <source>Commissioning report of %1</source>
        <translation>Inbetriebnahmebericht von %1</translation>
    </message>
    <message>
        <location line="-18"/>
        <source>no device %1@%2</source>
        <translation>kein Gerät %1@%2</translation>
    </message>
</context>
<context>
    <name>jumo::MapCommands</name>
    <message>
        <location filename="../app/cli/mapcommands.cpp" line="+145"/>
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
        <location line="+32"/>
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
        <location line="+52"/>
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
        <location line="+8"/>
        <source>&apos;%1&apos; is not a 16-bit hex word</source>
        <translation>&apos;%1&apos; ist kein 16-Bit-Hexwort</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;%1&apos; takes %2 words, %3 given</source>
        <translation>&apos;%1&apos; benötigt %2 Wörter, %3 angegeben</translation>
    </message>
</context>
<context>
    <name>jumo::MapLoader</name>
    <message>
        <location filename="../lib/protocol/maploader.cpp" line="+56"/>
        <source>malformed JSON at byte %1: %2</source>
        <translation>fehlerhaftes JSON bei Byte %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>malformed JSON at byte %1: a control character</source>
        <translation>fehlerhaftes JSON bei Byte %1: ein Steuerzeichen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the top level must be a JSON object</source>
        <translation>die oberste Ebene muss ein JSON-Objekt sein</translation>
    </message>
    <message>
        <location filename="../lib/protocol/jsonfieldreader.cpp" line="+52"/>
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
        <source>&apos;%1&apos; must be a string, not %2</source>
        <translation>&apos;%1&apos; muss ein Text sein, nicht %2</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&apos;%1&apos; must be an array of strings</source>
        <translation>&apos;%1&apos; muss ein Array von Texten sein</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;%1&apos; must contain only strings, not %2</source>
        <translation>&apos;%1&apos; darf nur Texte enthalten, nicht %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;%1&apos; must be true or false, not %2</source>
        <translation>&apos;%1&apos; muss true oder false sein, nicht %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>&apos;%1&apos; must be a whole number %2..%3, not %4</source>
        <translation>&apos;%1&apos; muss eine ganze Zahl %2..%3 sein, nicht %4</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>&apos;%1&apos; must be a number, not %2</source>
        <translation>&apos;%1&apos; muss eine Zahl sein, nicht %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos; must be a number %2..%3, not %4</source>
        <translation>&apos;%1&apos; muss eine Zahl %2..%3 sein, nicht %4</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&apos;%1&apos; may contain only %2, not %3</source>
        <translation>&apos;%1&apos; darf nur %2 enthalten, nicht %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos; lists %2 twice</source>
        <translation>&apos;%1&apos; nennt %2 zweimal</translation>
    </message>
    <message>
        <location line="-39"/>
        <source>&apos;%1&apos; is missing</source>
        <translation>&apos;%1&apos; fehlt</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>&apos;%1&apos; must be 0x followed by 4 hex digits, not &apos;%2&apos;</source>
        <translation>&apos;%1&apos; muss 0x gefolgt von 4 Hexziffern sein, nicht &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="-22"/>
        <source>&apos;%1&apos; must be a non-empty array of numbers</source>
        <translation>&apos;%1&apos; muss ein nicht leeres Array von Zahlen sein</translation>
    </message>
    <message>
        <location filename="../lib/protocol/maploader.cpp" line="+29"/>
        <source>family id &apos;%1&apos; must be lower case letters, digits and &apos;_&apos;</source>
        <translation>Familienkennung &apos;%1&apos; darf nur aus Kleinbuchstaben, Ziffern und &apos;_&apos; bestehen</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>&apos;entries&apos; must be a non-empty array</source>
        <translation>&apos;entries&apos; muss ein nicht leeres Array sein</translation>
    </message>
    <message>
        <location line="+25"/>
        <location line="+96"/>
        <source>&apos;%1&apos; is not a readable entry</source>
        <translation>&apos;%1&apos; ist kein lesbarer Eintrag</translation>
    </message>
    <message>
        <location line="+111"/>
        <source>&apos;protocol&apos; must be an object</source>
        <translation>&apos;protocol&apos; muss ein Objekt sein</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&apos;%1&apos; must be ABCD, CDAB, BADC or DCBA, not &apos;%2&apos;</source>
        <translation>&apos;%1&apos; muss ABCD, CDAB, BADC oder DCBA sein, nicht &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>unknown data format &apos;%1&apos;</source>
        <translation>unbekanntes Datenformat &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;dataFormats&apos; must list at least one format</source>
        <translation>&apos;dataFormats&apos; muss mindestens ein Format enthalten</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>&apos;identify&apos; must be a non-empty array of probes</source>
        <translation>&apos;identify&apos; muss ein nicht leeres Array von Prüfabfragen sein</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>a probe needs exactly one of textContains, maskNonZero, answers, exception</source>
        <translation>eine Prüfabfrage benötigt genau eines von textContains, maskNonZero, answers, exception</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;exceptions&apos; must be an object mapping codes to meanings</source>
        <translation>&apos;exceptions&apos; muss ein Objekt sein, das Codes ihren Bedeutungen zuordnet</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;%1&apos; is not an exception code with a text</source>
        <translation>&apos;%1&apos; ist kein Exception-Code mit Text</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>&apos;errorValues&apos; must be an object or null</source>
        <translation>&apos;errorValues&apos; muss ein Objekt oder null sein</translation>
    </message>
    <message>
        <location line="+71"/>
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
        <location line="-419"/>
        <location line="+420"/>
        <location line="+416"/>
        <location filename="../lib/protocol/overlapcheck.cpp" line="+70"/>
        <source>entry &apos;%1&apos; (%2)</source>
        <translation>Eintrag &apos;%1&apos; (%2)</translation>
    </message>
    <message>
        <location line="-406"/>
        <source>id must be lower case letters, digits and &apos;_&apos;</source>
        <translation>die Kennung darf nur aus Kleinbuchstaben, Ziffern und &apos;_&apos; bestehen</translation>
    </message>
    <message>
        <location line="+10"/>
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
        <location line="+3"/>
        <source>&apos;bytes&apos; is only for texts</source>
        <translation>&apos;bytes&apos; ist nur für Texte zulässig</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>&apos;min&apos; is greater than &apos;max&apos;</source>
        <translation>&apos;min&apos; ist größer als &apos;max&apos;</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>unknown control &apos;%1&apos;</source>
        <translation>unbekanntes Bedienelement &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a control needs a writable entry</source>
        <translation>ein Bedienelement benötigt einen schreibbaren Eintrag</translation>
    </message>
    <message>
        <location line="-251"/>
        <source>address range %1..%2 is empty</source>
        <translation>Adressbereich %1..%2 ist leer</translation>
    </message>
    <message>
        <location line="-323"/>
        <source>malformed JSON at byte %1: &apos;%2&apos; given twice in one object</source>
        <translation>fehlerhaftes JSON bei Byte %1: &apos;%2&apos; zweimal im selben Objekt angegeben</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>&apos;shortName&apos; must be 1 to 24 characters, not &apos;%1&apos;</source>
        <translation>&apos;shortName&apos; muss 1 bis 24 Zeichen lang sein, nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>&apos;configuredUnit&apos; names &apos;%1&apos;, which &apos;configuredUnits&apos; does not define</source>
        <translation>&apos;configuredUnit&apos; nennt &apos;%1&apos;, das &apos;configuredUnits&apos; nicht definiert</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>&apos;%1&apos; must be a readable bool entry or a single bit of a readable bit field</source>
        <translation>&apos;%1&apos; muss ein lesbarer Bool-Eintrag oder ein einzelnes Bit eines lesbaren Bitfelds sein</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>&apos;%1&apos; must be an array</source>
        <translation>&apos;%1&apos; muss ein Array sein</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>&apos;%1&apos; is a reserve, which the HMI does not read</source>
        <translation>&apos;%1&apos; ist eine Reserve, die die HMI nicht liest</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the scale &apos;%1&apos; must be a number, or an enum whose every text starts with one</source>
        <translation>die Skala &apos;%1&apos; muss eine Zahl sein oder eine Aufzählung, deren Texte alle mit einer Zahl beginnen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos; has a bar, so it must be a number, or an enum whose every text starts with one</source>
        <translation>&apos;%1&apos; hat einen Balken, muss also eine Zahl sein oder eine Aufzählung, deren Texte alle mit einer Zahl beginnen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos; must be a number</source>
        <translation>&apos;%1&apos; muss eine Zahl sein</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;faceplate&apos; must be an object</source>
        <translation>&apos;faceplate&apos; muss ein Objekt sein</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>unknown kind &apos;%1&apos; (expected power_unit or process_controller)</source>
        <translation>unbekannte Art &apos;%1&apos; (erwartet: power_unit oder process_controller)</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&apos;values&apos; must be a non-empty array</source>
        <translation>&apos;values&apos; muss ein nicht leeres Array sein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;values&apos; has %1 rows; a faceplate shows at most %2</source>
        <translation>&apos;values&apos; hat %1 Zeilen; ein Gerätebild der Übersicht zeigt höchstens %2</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&apos;max&apos; must be above &apos;min&apos;</source>
        <translation>&apos;max&apos; muss größer als &apos;min&apos; sein</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;from&apos; names one entry, or two whose product is the scale</source>
        <translation>&apos;from&apos; nennt einen Eintrag oder zwei, deren Produkt die Skala ist</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown scale &apos;%1&apos; (expected range, nominal or limit)</source>
        <translation>unbekannte Skala &apos;%1&apos; (erwartet: range, nominal oder limit)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;min&apos; and &apos;max&apos; are only for the scale &apos;range&apos;</source>
        <translation>&apos;min&apos; und &apos;max&apos; gibt es nur für die Skala &apos;range&apos;</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&apos;from&apos; is only for the scales &apos;nominal&apos; and &apos;limit&apos;</source>
        <translation>&apos;from&apos; gibt es nur für die Skalen &apos;nominal&apos; und &apos;limit&apos;</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&apos;program&apos; must be an object</source>
        <translation>&apos;program&apos; muss ein Objekt sein</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>&apos;alwaysAnswersAddress&apos; must be 1..247 or 255, not %1</source>
        <translation>&apos;alwaysAnswersAddress&apos; muss 1..247 oder 255 sein, nicht %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;processingTimeMaxMs&apos; is missing</source>
        <translation>&apos;processingTimeMaxMs&apos; fehlt</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>a probe must be an object</source>
        <translation>eine Probe muss ein Objekt sein</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>&apos;answers&apos; can only be true</source>
        <translation>&apos;answers&apos; kann nur true sein</translation>
    </message>
    <message>
        <location line="+52"/>
        <source>&apos;configuredUnits&apos; must be an object mapping ids to what decides the unit</source>
        <translation>&apos;configuredUnits&apos; muss ein Objekt sein, das IDs dem zuordnet, was die Einheit bestimmt</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;%1&apos; is no id (lower case letters, digits and &apos;_&apos;)</source>
        <translation>&apos;%1&apos; ist keine ID (Kleinbuchstaben, Ziffern und &apos;_&apos;)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos; needs a text that says what decides the unit</source>
        <translation>&apos;%1&apos; braucht einen Text, der sagt, was die Einheit bestimmt</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&apos;decimals&apos; and &apos;significantDigits&apos; are only for floats</source>
        <translation>&apos;decimals&apos; und &apos;significantDigits&apos; gibt es nur für Gleitkommazahlen</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>give &apos;decimals&apos; or &apos;significantDigits&apos;, not both</source>
        <translation>&apos;decimals&apos; oder &apos;significantDigits&apos; angeben, nicht beides</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>&apos;%1&apos; contains a control character (U+%2)</source>
        <translation>&apos;%1&apos; enthält ein Steuerzeichen (U+%2)</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>&apos;words&apos; is only for reserved blocks</source>
        <translation>&apos;words&apos; gilt nur für reservierte Blöcke</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>give &apos;unit&apos; or &apos;configuredUnit&apos;, not both</source>
        <translation>&apos;unit&apos; oder &apos;configuredUnit&apos; angeben, nicht beides</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>a unit is only for numbers</source>
        <translation>eine Einheit gibt es nur für Zahlen</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;%1&apos; is only for numbers</source>
        <translation>&apos;%1&apos; ist nur für Zahlen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos; %2 is outside what a %3 holds (%4..%5)</source>
        <translation>&apos;%1&apos; %2 liegt außerhalb dessen, was ein %3 fasst (%4..%5)</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>an entry cannot be an alias of itself</source>
        <translation>ein Eintrag kann kein Alias seiner selbst sein</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>an action needs a writable entry</source>
        <translation>eine Aktion braucht einen beschreibbaren Eintrag</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&apos;action&apos; is for command words (bit fields, enums, integers), not for a %1</source>
        <translation>&apos;action&apos; ist für Befehlswörter (Bitfelder, Aufzählungen, Ganzzahlen), nicht für ein %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>unknown poll class &apos;%1&apos; (expected alarm, live or setting)</source>
        <translation>unbekannte Abfrageklasse &apos;%1&apos; (erwartet: alarm, live oder setting)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;poll&apos; is only for entries that are read (not write-only, not an alias)</source>
        <translation>&apos;poll&apos; ist nur für Einträge, die gelesen werden (nicht nur schreibbar, kein Alias)</translation>
    </message>
    <message>
        <location line="+17"/>
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
        <location line="+15"/>
        <source>&apos;values&apos;: the label &apos;%1&apos; of %2 would be written as %3 (a label must not be another value&apos;s number, nor another label in other case)</source>
        <translation>&apos;values&apos;: die Bezeichnung &apos;%1&apos; von %2 würde als %3 geschrieben (eine Bezeichnung darf weder die Zahl eines anderen Werts noch eine andere Bezeichnung in anderer Schreibweise sein)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&apos;default&apos; is only for writable entries</source>
        <translation>&apos;default&apos; gibt es nur für beschreibbare Einträge</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&apos;default&apos; is only for numbers, enums and booleans</source>
        <translation>&apos;default&apos; gibt es nur für Zahlen, Aufzählungen und Wahrheitswerte</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;default&apos; of a boolean must be true or false, not %1</source>
        <translation>&apos;default&apos; eines Wahrheitswerts muss true oder false sein, nicht %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;default&apos; must be a number, not %1</source>
        <translation>&apos;default&apos; muss eine Zahl sein, nicht %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;default&apos; %1 is none of the enum&apos;s values</source>
        <translation>&apos;default&apos; %1 ist keiner der Werte der Aufzählung</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&apos;default&apos; of a %1 must be a whole number, not %2</source>
        <translation>&apos;default&apos; eines %1 muss eine ganze Zahl sein, nicht %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;default&apos; %1 is outside the entry&apos;s range %2..%3</source>
        <translation>&apos;default&apos; %1 liegt außerhalb des Bereichs %2..%3 des Eintrags</translation>
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
        <location line="+7"/>
        <source>a bit must be an object</source>
        <translation>ein Bit muss ein Objekt sein</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1, bit %2</source>
        <translation>%1, Bit %2</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>bit number must be 0..15</source>
        <translation>Bitnummer muss 0..15 sein</translation>
    </message>
    <message>
        <location line="+6"/>
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
        <location line="+6"/>
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
        <location line="+13"/>
        <source>entry &apos;%1&apos;, bit %2</source>
        <translation>Eintrag &apos;%1&apos;, Bit %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;stateFrom&apos; is only for write-only words (a readable word reports its own bits)</source>
        <translation>&apos;stateFrom&apos; gibt es nur für Nur-Schreib-Wörter (ein lesbares Wort meldet seine Bits selbst)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;stateFrom&apos; is only for single bits, not for a field of %1</source>
        <translation>&apos;stateFrom&apos; ist nur für einzelne Bits, nicht für ein Feld von %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;stateFrom&apos; must name a single bit as ENTRY.BIT, not &apos;%1&apos;</source>
        <translation>&apos;stateFrom&apos; muss ein einzelnes Bit als ENTRY.BIT nennen, nicht &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;stateFrom&apos; must name a single bit of a readable bit field</source>
        <translation>&apos;stateFrom&apos; muss ein einzelnes Bit eines lesbaren Bitfelds nennen</translation>
    </message>
    <message>
        <location line="+13"/>
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
        <location line="+8"/>
        <source>a link is a pair of references</source>
        <translation>eine Verknüpfung ist ein Paar von Verweisen</translation>
    </message>
    <message>
        <location line="+21"/>
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
        <location filename="../lib/protocol/overlapcheck.cpp" line="-33"/>
        <source>&apos;%1&apos; (%2..%3)</source>
        <translation>&apos;%1&apos; (%2..%3)</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>words %1..%2 overlap entry %3</source>
        <translation>Wörter %1..%2 überschneiden sich mit Eintrag %3</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source> and %n more entries</source>
        <translation>
            <numerusform> und %n weiteren Eintrag</numerusform>
            <numerusform> und %n weiteren Einträgen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+15"/>
        <source>%n more group(s) of overlapping entries not listed</source>
        <translation>
            <numerusform>%n weitere Gruppe überlappender Einträge nicht aufgeführt</numerusform>
            <numerusform>%n weitere Gruppen überlappender Einträge nicht aufgeführt</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>jumo::MbapFramer</name>
    <message>
        <location filename="../lib/bus/mbapframer.cpp" line="+30"/>
        <source>a header with protocol id %1 (Modbus is 0): %2</source>
        <translation>ein Header mit Protokoll-ID %1 (Modbus ist 0): %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a header with length %1 (a Modbus TCP frame has %2..%3): %4</source>
        <translation>ein Header mit Länge %1 (ein Modbus-TCP-Rahmen hat %2..%3): %4</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>a frame whose length does not fit its content: %1</source>
        <translation>ein Rahmen, dessen Länge nicht zu seinem Inhalt passt: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a reply with transaction id %1 (%2 expected)</source>
        <translation>eine Antwort mit Transaktions-ID %1 (%2 erwartet)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>a reply with transaction id %1 while nothing was asked</source>
        <translation>eine Antwort mit Transaktions-ID %1, obwohl nichts angefragt war</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a reply from unit %1 to a request for unit %2</source>
        <translation>eine Antwort von Unit %1 auf eine Anfrage an Unit %2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the gateway sent %1</source>
        <translation>das Gateway sandte %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>no reply within %1 ms</source>
        <translation>keine Antwort innerhalb von %1 ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an incomplete reply within %1 ms (%2 byte(s): %3)</source>
        <translation>eine unvollständige Antwort innerhalb von %1 ms (%2 Byte: %3)</translation>
    </message>
</context>
<context>
    <name>jumo::MqttClient</name>
    <message>
        <location filename="../lib/mqtt/mqttclient.cpp" line="+38"/>
        <source>the broker did not answer within the keepalive time</source>
        <translation>der Broker hat innerhalb der Keepalive-Zeit nicht geantwortet</translation>
    </message>
    <message>
        <location line="+70"/>
        <source>cannot make an MQTT client: %1</source>
        <translation>MQTT-Client lässt sich nicht anlegen: %1</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>cannot use the user name: %1</source>
        <translation>Der Benutzername ist nicht verwendbar: %1</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>cannot read the TLS file %1</source>
        <translation>Die TLS-Datei %1 ist nicht lesbar</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>a client certificate needs its key, and a key its certificate</source>
        <translation>Ein Client-Zertifikat braucht seinen Schlüssel, ein Schlüssel sein Zertifikat</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>cannot set up TLS: %1</source>
        <translation>TLS lässt sich nicht einrichten: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>cannot set the last will: %1</source>
        <translation>Der letzte Wille (Last Will) lässt sich nicht setzen: %1</translation>
    </message>
    <message>
        <location line="+179"/>
        <source>the broker refused the connection: %1</source>
        <translation>Der Broker hat die Verbindung abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+22"/>
        <source>the broker closed the connection</source>
        <translation>Der Broker hat die Verbindung geschlossen</translation>
    </message>
</context>
<context>
    <name>jumo::MqttSettings</name>
    <message>
        <location filename="../lib/mqtt/mqttsettings.cpp" line="+19"/>
        <source>&apos;%1&apos; is no broker address: %2 (use mqtt://[USER@]HOST[:PORT] or mqtts://...)</source>
        <translation>&apos;%1&apos; ist keine Broker-Adresse: %2 (mqtt://[BENUTZER@]HOST[:PORT] oder mqtts://... angeben)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>unknown scheme &apos;%1&apos;</source>
        <translation>unbekanntes Schema &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no host</source>
        <translation>kein Host</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a password in the address can be read by every user of this computer; use a password file or JUMO_MQTT_PASSWORD</source>
        <translation>ein Passwort in der Adresse kann jeder Benutzer dieses Rechners lesen; eine Passwortdatei oder JUMO_MQTT_PASSWORD verwenden</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>an address has no path</source>
        <translation>eine Adresse hat keinen Pfad</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>an address has no query</source>
        <translation>eine Adresse hat keine Abfrage</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>port out of range</source>
        <translation>Port außerhalb des Bereichs</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>a password needs a user name: mqtt://USER@HOST or --username</source>
        <translation>ein Passwort braucht einen Benutzernamen: mqtt://BENUTZER@HOST oder --username</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TLS files need an mqtts:// broker</source>
        <translation>TLS-Dateien brauchen einen mqtts://-Broker</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>--tls-cert and --tls-key go together</source>
        <translation>--tls-cert und --tls-key gehören zusammen</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>cannot read the password file %1</source>
        <translation>Die Passwortdatei %1 ist nicht lesbar</translation>
    </message>
</context>
<context>
    <name>jumo::NavigationList</name>
    <message>
        <location filename="../ui/navigationlist.cpp" line="+117"/>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>lost</source>
        <translation>verloren</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>jumo::ParameterEditModel</name>
    <message>
        <location filename="../lib/models/parametereditmodel.cpp" line="+166"/>
        <location line="+271"/>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <location line="-271"/>
        <location line="+273"/>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <location line="-254"/>
        <source>write-only</source>
        <translation>nur schreibbar</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1 (stale)</source>
        <translation>%1 (veraltet)</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Not written: %1</source>
        <translation>Nicht geschrieben: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Writing...</source>
        <translation>Wird geschrieben...</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Confirmed: %1</source>
        <translation>Bestätigt: %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <location filename="../ui/parametereditor.cpp" line="+170"/>
        <source>Confirmed by read-back: %1</source>
        <translation>Durch Rücklesen bestätigt: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Refused: %1</source>
        <translation>Abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Unknown, check the device: %1</source>
        <translation>Unbekannt, bitte am Gerät prüfen: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+16"/>
        <source>%1 (%n changed)</source>
        <translation>
            <numerusform>%1 (%n geändert)</numerusform>
            <numerusform>%1 (%n geändert)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+47"/>
        <source>EEPROM</source>
        <translation>EEPROM</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RAM</source>
        <translation>RAM</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>%1, register %2, %3</source>
        <translation>%1, Register %2, %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Changed: %1 waits to be written</source>
        <translation>Geändert: %1 wartet darauf, geschrieben zu werden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Precondition: %1</source>
        <translation>Voraussetzung: %1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Status: %1</source>
        <translation>Status: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Last known value: %1, %2 s ago</source>
        <translation>Letzter bekannter Wert: %1, vor %2 s</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The device cannot report this value.</source>
        <translation>Das Gerät kann diesen Wert nicht melden.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not written yet</source>
        <translation>Noch nicht geschrieben</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Stored in EEPROM: every write wears it (about 10,000 write cycles).</source>
        <translation>Im EEPROM gespeichert: jedes Schreiben nutzt es ab (etwa 10.000 Schreibzyklen).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Kept in RAM: lost when the device is switched off.</source>
        <translation>Im RAM gehalten: geht beim Ausschalten des Geräts verloren.</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device value</source>
        <translation>Gerätewert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New value</source>
        <translation>Neuer Wert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Storage</source>
        <translation>Speicherort</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Last write</source>
        <translation>Letztes Schreiben</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;%1&apos; is no parameter listed here</source>
        <translation>„%1“ ist kein hier aufgeführter Parameter</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read-only mode: nothing is changed or written</source>
        <translation>Nur-Lese-Modus: es wird nichts geändert oder geschrieben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a write is under way: changes wait until it has ended</source>
        <translation>es wird gerade geschrieben: Änderungen warten, bis das beendet ist</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>&apos;%1&apos; is no number that can be read one way only: write it without thousands separators</source>
        <translation>„%1“ ist keine eindeutig lesbare Zahl: bitte ohne Tausenderpunkte schreiben</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>%1 is not a whole number: %2 takes whole numbers only</source>
        <translation>%1 ist keine ganze Zahl: %2 nimmt nur ganze Zahlen an</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 or more</source>
        <translation>%1 oder mehr</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>up to %1</source>
        <translation>bis %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is out of range: %2 takes %3</source>
        <translation>%1 liegt außerhalb des Bereichs: %2 nimmt %3 an</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>%1 already holds %2: no change</source>
        <translation>%1 hat bereits %2: keine Änderung</translation>
    </message>
</context>
<context>
    <name>jumo::ParameterEditor</name>
    <message>
        <location filename="../ui/parametereditor.cpp" line="-90"/>
        <source>Lo&amp;ad backup...</source>
        <translation>Sicherung lade&amp;n...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Dis&amp;card changes</source>
        <translation>Änderungen &amp;verwerfen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>S&amp;top after this write</source>
        <translation>Nach diesem Schreiben anhal&amp;ten</translation>
    </message>
    <message numerus="yes">
        <location line="+18"/>
        <source>All %n parameter(s) listed here are stored in EEPROM: every write wears it (about 10,000 write cycles). Write only what needs changing.</source>
        <translation>
            <numerusform>Der hier aufgeführte Parameter ist im EEPROM gespeichert: jedes Schreiben nutzt es ab (etwa 10.000 Schreibzyklen). Nur schreiben, was sich ändern muss.</numerusform>
            <numerusform>Alle %n hier aufgeführten Parameter sind im EEPROM gespeichert: jedes Schreiben nutzt es ab (etwa 10.000 Schreibzyklen). Nur schreiben, was sich ändern muss.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <source>%1 of the %n parameter(s) listed here are stored in EEPROM: every write wears it (about 10,000 write cycles). Write only what needs changing.</source>
        <translation>
            <numerusform>%1 des hier aufgeführten Parameters ist im EEPROM gespeichert: jedes Schreiben nutzt es ab (etwa 10.000 Schreibzyklen). Nur schreiben, was sich ändern muss.</numerusform>
            <numerusform>%1 der %n hier aufgeführten Parameter sind im EEPROM gespeichert: jedes Schreiben nutzt es ab (etwa 10.000 Schreibzyklen). Nur schreiben, was sich ändern muss.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The parameters listed here are kept in RAM: the device loses them when it is switched off.</source>
        <translation>Die hier aufgeführten Parameter werden im RAM gehalten: das Gerät verliert sie beim Ausschalten.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This device has no parameters to edit.</source>
        <translation>Dieses Gerät hat keine Parameter zum Bearbeiten.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Search:</source>
        <translation>S&amp;uchen:</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Name, id or address</source>
        <translation>Name, Kennung oder Adresse</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Shows the parameters whose name, id or register address contains this text (Ctrl+F).</source>
        <translation>Zeigt die Parameter, deren Name, Kennung oder Registeradresse diesen Text enthält (Strg+F).</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>%1 (stale)</source>
        <translation>%1 (veraltet)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>EEPROM</source>
        <translation>EEPROM</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>RAM</source>
        <translation>RAM</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Take back this change</source>
        <translation>Diese Änderung zurücknehmen</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Not taken for %1: %2</source>
        <translation>Für %1 nicht übernommen: %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+136"/>
        <source>Shows the changes with the device&apos;s values first; nothing is written before you confirm.</source>
        <translation>Zeigt zuerst die Änderungen mit den Werten des Geräts; geschrieben wird erst nach Ihrer Bestätigung.</translation>
    </message>
    <message>
        <location line="-135"/>
        <location line="+143"/>
        <source>Fills in the values of a parameter backup file that differ from the device, to check before writing them.</source>
        <translation>Trägt die Werte einer Parametersicherung ein, die vom Gerät abweichen, zum Prüfen vor dem Schreiben.</translation>
    </message>
    <message>
        <location line="-141"/>
        <source>Drops every change that has not been written.</source>
        <translation>Verwirft jede Änderung, die noch nicht geschrieben ist.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The write under way ends as usual; the changes after it are not written and stay.</source>
        <translation>Das laufende Schreiben endet wie gewohnt; die Änderungen danach werden nicht geschrieben und bleiben erhalten.</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+369"/>
        <source>stopped before its turn</source>
        <translation>angehalten, bevor es an der Reihe war</translation>
    </message>
    <message>
        <location line="-364"/>
        <source>Load parameter backup</source>
        <translation>Parametersicherung laden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter files (*.json)</source>
        <translation>Parameterdateien (*.json)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Writing %1 of %2...</source>
        <translation>Schreibe %1 von %2...</translation>
    </message>
    <message>
        <location line="+85"/>
        <source>No parameter matches &quot;%1&quot;.</source>
        <translation>Kein Parameter passt zu „%1“.</translation>
    </message>
    <message numerus="yes">
        <location line="+19"/>
        <source>&amp;Write %n change(s)</source>
        <translation>
            <numerusform>%n Änderung s&amp;chreiben</numerusform>
            <numerusform>%n Änderungen s&amp;chreiben</numerusform>
        </translation>
    </message>
    <message>
        <location line="+0"/>
        <source>&amp;Write changes</source>
        <translation>Änderungen s&amp;chreiben</translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+141"/>
        <source>Read-only mode: nothing is written to the devices.</source>
        <translation>Nur-Lese-Modus: Es wird nichts auf die Geräte geschrieben.</translation>
    </message>
    <message>
        <location line="-139"/>
        <source>Not now: %1. The changes can be written once the device answers.</source>
        <translation>Jetzt nicht: %1. Die Änderungen können geschrieben werden, sobald das Gerät antwortet.</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>%n change(s) not written yet</source>
        <translation>
            <numerusform>%n Änderung noch nicht geschrieben</numerusform>
            <numerusform>%n Änderungen noch nicht geschrieben</numerusform>
        </translation>
    </message>
    <message>
        <location line="+0"/>
        <source>No changes</source>
        <translation>Keine Änderungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+31"/>
        <source>Read-only mode: nothing is changed or written.</source>
        <translation>Nur-Lese-Modus: Es wird nichts geändert oder geschrieben.</translation>
    </message>
    <message>
        <location line="-19"/>
        <source>the device stopped answering (%1)</source>
        <translation>das Gerät antwortet nicht mehr (%1)</translation>
    </message>
    <message numerus="yes">
        <location line="+13"/>
        <source>%n change(s) discarded.</source>
        <translation>
            <numerusform>%n Änderung verworfen.</numerusform>
            <numerusform>%n Änderungen verworfen.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+10"/>
        <location line="+99"/>
        <source>Wait until the read or write under way has ended.</source>
        <translation>Bitte warten, bis das laufende Lesen oder Schreiben beendet ist.</translation>
    </message>
    <message>
        <location line="-92"/>
        <location line="+12"/>
        <location line="+24"/>
        <source>Not loaded: %1</source>
        <translation>Nicht geladen: %1</translation>
    </message>
    <message>
        <location line="-30"/>
        <source>Not loaded: %1: %2</source>
        <translation>Nicht geladen: %1: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Not loaded: %1. A backup is compared with the device, which must answer.</source>
        <translation>Nicht geladen: %1. Eine Sicherung wird mit dem Gerät verglichen, das dafür antworten muss.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Reading the device&apos;s parameters to compare with %1...</source>
        <translation>Die Parameter des Geräts werden zum Vergleich mit %1 gelesen...</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>and %n more</source>
        <translation>
            <numerusform>und %n weiterer</numerusform>
            <numerusform>und %n weitere</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not loaded: these could not be read from the device to compare: %1</source>
        <translation>Nicht geladen: diese konnten zum Vergleich nicht vom Gerät gelesen werden: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Not loaded: a write started meanwhile.</source>
        <translation>Nicht geladen: inzwischen hat ein Schreiben begonnen.</translation>
    </message>
    <message numerus="yes">
        <location line="+22"/>
        <source>%1: %n value(s) that differ from the device filled in as changes; check them and write them.</source>
        <translation>
            <numerusform>%1: %n vom Gerät abweichender Wert als Änderung eingetragen; bitte prüfen und schreiben.</numerusform>
            <numerusform>%1: %n vom Gerät abweichende Werte als Änderungen eingetragen; bitte prüfen und schreiben.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1: every parameter listed here matches the device, nothing to fill in.</source>
        <translation>%1: jeder hier aufgeführte Parameter stimmt mit dem Gerät überein, nichts einzutragen.</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n parameter(s) the file does not hold are left as they are.</source>
        <translation>
            <numerusform>%n Parameter, den die Datei nicht enthält, bleibt, wie er ist.</numerusform>
            <numerusform>%n Parameter, die die Datei nicht enthält, bleiben, wie sie sind.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n differing value(s) of the file are not on this page (setpoints and the like); the Parameters dialog restores them.</source>
        <translation>
            <numerusform>%n abweichender Wert der Datei steht nicht auf dieser Seite (Sollwerte und dergleichen); der Parameter-Dialog stellt ihn wieder her.</numerusform>
            <numerusform>%n abweichende Werte der Datei stehen nicht auf dieser Seite (Sollwerte und dergleichen); der Parameter-Dialog stellt sie wieder her.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Not taken: %1</source>
        <translation>Nicht übernommen: %1</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Nothing to write: no parameter is changed.</source>
        <translation>Nichts zu schreiben: kein Parameter ist geändert.</translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+36"/>
        <source>Not written: %1. The changes stay and can be written once the device answers.</source>
        <translation>Nicht geschrieben: %1. Die Änderungen bleiben und können geschrieben werden, sobald das Gerät antwortet.</translation>
    </message>
    <message numerus="yes">
        <location line="+28"/>
        <source>Writing %n change(s), each verified by reading it back...</source>
        <translation>
            <numerusform>%n Änderung wird geschrieben und durch Rücklesen geprüft...</numerusform>
            <numerusform>%n Änderungen werden geschrieben, jede durch Rücklesen geprüft...</numerusform>
        </translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the write of %1 ended unknown; check the device first</source>
        <translation>das Schreiben von %1 endete unbekannt; bitte zuerst das Gerät prüfen</translation>
    </message>
    <message numerus="yes">
        <location line="+35"/>
        <source>%1 of %n change(s) written and confirmed by read-back.</source>
        <translation>
            <numerusform>%1 von %n Änderung geschrieben und durch Rücklesen bestätigt.</numerusform>
            <numerusform>%1 von %n Änderungen geschrieben und durch Rücklesen bestätigt.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n refused.</source>
        <translation>
            <numerusform>%n abgelehnt.</numerusform>
            <numerusform>%n abgelehnt.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n with an unknown outcome: check the device.</source>
        <translation>
            <numerusform>%n mit unbekanntem Ausgang: bitte am Gerät prüfen.</numerusform>
            <numerusform>%n mit unbekanntem Ausgang: bitte am Gerät prüfen.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n not written (%1).</source>
        <translation>
            <numerusform>%n nicht geschrieben (%1).</numerusform>
            <numerusform>%n nicht geschrieben (%1).</numerusform>
        </translation>
    </message>
    <message>
        <location line="+0"/>
        <source>stopped</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What was not confirmed stays as a change; see &quot;Last write&quot;.</source>
        <translation>Was nicht bestätigt ist, bleibt als Änderung; siehe „Letztes Schreiben“.</translation>
    </message>
</context>
<context>
    <name>jumo::ParameterReadJob</name>
    <message>
        <location filename="../lib/commissioning/parameterreadjob.cpp" line="+18"/>
        <source>unknown device</source>
        <translation>unbekanntes Gerät</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>the device was removed</source>
        <translation>das Gerät wurde entfernt</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>could not be read: %1</source>
        <translation>konnte nicht gelesen werden: %1</translation>
    </message>
</context>
<context>
    <name>jumo::ParameterSet</name>
    <message>
        <location filename="../lib/commissioning/parameterset.cpp" line="+73"/>
        <source>not a parameter file: %1 at byte %2</source>
        <translation>keine Parameterdatei: %1 bei Byte %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>not a parameter file: a control character at byte %1</source>
        <translation>keine Parameterdatei: ein Steuerzeichen bei Byte %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the parameter file names &apos;%1&apos; twice (again at byte %2): which value is meant is not clear</source>
        <translation>die Parameterdatei nennt &apos;%1&apos; zweimal (erneut bei Byte %2): welcher Wert gemeint ist, ist nicht klar</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not a parameter file (no &quot;format&quot;: &quot;jumo-parameters&quot;)</source>
        <translation>keine Parameterdatei (kein &quot;format&quot;: &quot;jumo-parameters&quot;)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>parameter file version %1 is not supported (expected %2)</source>
        <translation>Version %1 der Parameterdatei wird nicht unterstützt (erwartet: %2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the parameter file lacks &quot;family&quot; or &quot;values&quot;</source>
        <translation>der Parameterdatei fehlt &quot;family&quot; oder &quot;values&quot;</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;time&apos; is no ISO 8601 time: %1</source>
        <translation>&apos;time&apos; ist keine ISO-8601-Zeit: %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&apos;identity&apos; must be an object</source>
        <translation>&apos;identity&apos; muss ein Objekt sein</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the value of &apos;%1&apos; must be a text</source>
        <translation>der Wert von &apos;%1&apos; muss ein Text sein</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>the file is for the family %1, the device is %2</source>
        <translation>die Datei gehört zur Gerätefamilie %1, das Gerät ist %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the file is from software version %1, the device runs %2</source>
        <translation>die Datei stammt von Softwareversion %1, auf dem Gerät läuft %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;%1&apos; in the file is no parameter of %2</source>
        <translation>&apos;%1&apos; in der Datei ist kein Parameter von %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&apos;%1&apos; in the file: %2</source>
        <translation>&apos;%1&apos; in der Datei: %2</translation>
    </message>
</context>
<context>
    <name>jumo::ParameterTransfer</name>
    <message>
        <location filename="../lib/commissioning/parametertransfer.cpp" line="+14"/>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
</context>
<context>
    <name>jumo::ParameterValueDelegate</name>
    <message>
        <location filename="../ui/parametervaluedelegate.cpp" line="+35"/>
        <source>%1 to %2</source>
        <translation>%1 bis %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 or more</source>
        <translation>%1 oder mehr</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>up to %1</source>
        <translation>bis %1</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>On</source>
        <translation>Ein</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Takes %1</source>
        <translation>Nimmt %1 an</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>The device shows %n decimal(s)</source>
        <translation>
            <numerusform>Das Gerät zeigt %n Nachkommastelle</numerusform>
            <numerusform>Das Gerät zeigt %n Nachkommastellen</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enter takes the value, Escape leaves it as it was; an empty field drops the change.</source>
        <translation>Eingabe übernimmt den Wert, Esc lässt ihn, wie er war; ein leeres Feld verwirft die Änderung.</translation>
    </message>
</context>
<context>
    <name>jumo::ParameterWriteJob</name>
    <message>
        <location filename="../lib/commissioning/parameterwritejob.cpp" line="+34"/>
        <source>cancelled after %1 of %2 writes</source>
        <translation>abgebrochen nach %1 von %2 Schreibvorgängen</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n write(s) failed</source>
        <translation>
            <numerusform>%n Schreibvorgang fehlgeschlagen</numerusform>
            <numerusform>%n Schreibvorgänge fehlgeschlagen</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>jumo::ParameterWritePreview</name>
    <message>
        <location filename="../ui/parameterwritepreview.cpp" line="+21"/>
        <source>Write parameters</source>
        <translation>Parameter schreiben</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>Write these %n change(s) to %1? Each is written once and verified by reading it back.</source>
        <translation>
            <numerusform>Diese %n Änderung auf %1 schreiben? Sie wird einmal geschrieben und durch Rücklesen geprüft.</numerusform>
            <numerusform>Diese %n Änderungen auf %1 schreiben? Jede wird einmal geschrieben und durch Rücklesen geprüft.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source>%n of them are stored in EEPROM, which wears with every write.</source>
        <translation>
            <numerusform>%n davon ist im EEPROM gespeichert, das sich mit jedem Schreiben abnutzt.</numerusform>
            <numerusform>%n davon sind im EEPROM gespeichert, das sich mit jedem Schreiben abnutzt.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device value</source>
        <translation>Gerätewert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>New value</source>
        <translation>Neuer Wert</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Last write</source>
        <translation>Letztes Schreiben</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>A change whose last write is unknown may already be on the device: writing it again sends the same value once more.</source>
        <translation>Eine Änderung, deren letztes Schreiben unbekannt endete, kann schon auf dem Gerät sein: erneutes Schreiben sendet denselben Wert noch einmal.</translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source>&amp;Write %n change(s)</source>
        <translation>
            <numerusform>%n Änderung s&amp;chreiben</numerusform>
            <numerusform>%n Änderungen s&amp;chreiben</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
</context>
<context>
    <name>jumo::ParametersDialog</name>
    <message>
        <location filename="../ui/parametersdialog.cpp" line="+22"/>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Parameters of %1 at address %2</source>
        <translation>Parameter von %1 an Adresse %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Parameter</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation>Ergebnis</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Parameter files (*.json)</source>
        <translation>Parameterdateien (*.json)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Back up to file...</source>
        <translation>In Datei sichern...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Compare with file...</source>
        <translation>Mit Datei vergleichen...</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore from file...</source>
        <translation>Aus Datei wiederherstellen...</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Back up parameters</source>
        <translation>Parameter sichern</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Compare with</source>
        <translation>Vergleichen mit</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Restore from</source>
        <translation>Wiederherstellen aus</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Restore parameters</source>
        <translation>Parameter wiederherstellen</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>Write %n parameter(s) that differ to the device? Each is verified by reading it back; EEPROM parameters wear with every write.</source>
        <translation>
            <numerusform>%n abweichenden Parameter auf das Gerät schreiben? Er wird durch Rücklesen geprüft; EEPROM-Parameter verschleißen mit jedem Schreiben.</numerusform>
            <numerusform>%n abweichende Parameter auf das Gerät schreiben? Jeder wird durch Rücklesen geprüft; EEPROM-Parameter verschleißen mit jedem Schreiben.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+52"/>
        <source>Cannot read %1</source>
        <translation>%1 kann nicht gelesen werden</translation>
    </message>
    <message>
        <location line="+26"/>
        <location line="+29"/>
        <source>Reading all parameters...</source>
        <translation>Alle Parameter werden gelesen...</translation>
    </message>
    <message>
        <location line="-24"/>
        <source>Not saved: these could not be read: %1</source>
        <translation>Nicht gesichert: diese konnten nicht gelesen werden: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+8"/>
        <source>%n parameter(s) saved to %1</source>
        <translation>
            <numerusform>%n Parameter in %1 gesichert</numerusform>
            <numerusform>%n Parameter in %1 gesichert</numerusform>
        </translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+43"/>
        <source>Refused: %1</source>
        <translation>Abgelehnt: %1</translation>
    </message>
    <message>
        <location line="-26"/>
        <location line="+21"/>
        <source>Could not read: %1</source>
        <translation>Nicht lesbar: %1</translation>
    </message>
    <message>
        <location line="-16"/>
        <source>The device matches the file.</source>
        <translation>Das Gerät stimmt mit der Datei überein.</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n parameter(s) differ from the file.</source>
        <translation>
            <numerusform>%n Parameter weicht von der Datei ab.</numerusform>
            <numerusform>%n Parameter weichen von der Datei ab.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+29"/>
        <source>Nothing to write: the %n parameter(s) that differ are missing from the file and are left as they are.</source>
        <translation>
            <numerusform>Nichts zu schreiben: Der %n abweichende Parameter fehlt in der Datei und bleibt unverändert.</numerusform>
            <numerusform>Nichts zu schreiben: Die %n abweichenden Parameter fehlen in der Datei und bleiben unverändert.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The device already matches the file: nothing to write.</source>
        <translation>Das Gerät stimmt bereits mit der Datei überein: nichts zu schreiben.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Nothing written.</source>
        <translation>Nichts geschrieben.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Writing...</source>
        <translation>Schreiben...</translation>
    </message>
    <message numerus="yes">
        <location line="+14"/>
        <source>Cancelled after %n verified write(s).</source>
        <translation>
            <numerusform>Abgebrochen nach %n geprüften Schreibvorgang.</numerusform>
            <numerusform>Abgebrochen nach %n geprüften Schreibvorgängen.</numerusform>
        </translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 written and verified, %2 failed: see the table.</source>
        <translation>%1 geschrieben und geprüft, %2 fehlgeschlagen: siehe Tabelle.</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n parameter(s) restored and verified.</source>
        <translation>
            <numerusform>%n Parameter wiederhergestellt und geprüft.</numerusform>
            <numerusform>%n Parameter wiederhergestellt und geprüft.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>jumo::PollSelection</name>
    <message>
        <location filename="../lib/bus/pollselection.cpp" line="+40"/>
        <source>&apos;%1&apos; is no entry of %2 (jumoctl map %2 lists them) nor &apos;faceplate&apos; or &apos;alarms&apos;</source>
        <translation>&apos;%1&apos; ist weder ein Eintrag von %2 (jumoctl map %2 listet sie auf) noch &apos;faceplate&apos; oder &apos;alarms&apos;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 &apos;%2&apos; cannot be read</source>
        <translation>%1 &apos;%2&apos; kann nicht gelesen werden</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 &apos;%2&apos; is a reserve: it means nothing and is never published</source>
        <translation>%1 &apos;%2&apos; ist eine Reserve: sie bedeutet nichts und wird nie veröffentlicht</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>name at least one entry of %1 to poll</source>
        <translation>mindestens einen Eintrag von %1 zum Abfragen angeben</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>&apos;%1&apos; is not FAMILY:ENTRY[,ENTRY...] (entries, &apos;faceplate&apos; or &apos;alarms&apos;)</source>
        <translation>&apos;%1&apos; ist nicht FAMILIE:EINTRAG[,EINTRAG...] (Einträge, &apos;faceplate&apos; oder &apos;alarms&apos;)</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>unknown family &apos;%1&apos; (families: %2)</source>
        <translation>unbekannte Familie &apos;%1&apos; (Familien: %2)</translation>
    </message>
</context>
<context>
    <name>jumo::PortAccess</name>
    <message>
        <location filename="../lib/bus/portaccess.cpp" line="+138"/>
        <source>there is no such port: is the adapter plugged in? &apos;jumoctl ports&apos; lists the serial ports.</source>
        <translation>diese Schnittstelle gibt es nicht: Ist der Adapter eingesteckt? &apos;jumoctl ports&apos; listet die seriellen Schnittstellen auf.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no permission to reach %1.</source>
        <translation>keine Berechtigung, %1 zu erreichen.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no permission: %1 (owner %2, group %3, mode %4) is not open to a group. Ask the administrator to give it to the group dialout (a udev rule).</source>
        <translation>keine Berechtigung: %1 (Eigentümer %2, Gruppe %3, Modus %4) ist für keine Gruppe freigegeben. Bitten Sie den Administrator, es der Gruppe dialout zu geben (eine udev-Regel).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no permission: %1 belongs to the group &apos;%2&apos;; you are in it, but this login started before you joined: log out and in again.</source>
        <translation>keine Berechtigung: %1 gehört der Gruppe &apos;%2&apos;; Sie sind Mitglied, aber diese Anmeldung begann vor dem Beitritt: ab- und wieder anmelden.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no permission: %1 belongs to the group &apos;%2&apos;. Join it with &apos;sudo usermod -aG %2 $USER&apos;, then log out and in again.</source>
        <translation>keine Berechtigung: %1 gehört der Gruppe &apos;%2&apos;. Treten Sie ihr mit &apos;sudo usermod -aG %2 $USER&apos; bei, dann ab- und wieder anmelden.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 is in use by another program (the system does not tell which).</source>
        <translation>%1 wird von einem anderen Programm benutzt (das System sagt nicht, von welchem).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (PID %2)</source>
        <translation>%1 (PID %2)</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>a process</source>
        <translation>einem Prozess</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is in use by %2: close it there first.</source>
        <translation>%1 wird benutzt von %2: dort zuerst schließen.</translation>
    </message>
</context>
<context>
    <name>jumo::PortCommands</name>
    <message>
        <location filename="../app/cli/portcommands.cpp" line="+53"/>
        <source>Lists the serial ports: USB adapters under their stable /dev/serial/by-id names (give that name to --port: it still finds the adapter when it comes back as another ttyUSBn), with description, serial number, the device each is now, and whether it can be opened. Pseudo-terminals are not listed.</source>
        <translation>Listet die seriellen Schnittstellen auf: USB-Adapter unter ihren stabilen /dev/serial/by-id-Namen (diesen Namen bei --port angeben: er findet den Adapter auch, wenn er als anderes ttyUSBn wiederkommt), mit Beschreibung, Seriennummer, der aktuellen Gerätedatei und ob sie sich öffnen lässt. Pseudo-Terminals werden nicht aufgelistet.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Print a JSON array.</source>
        <translation>Ein JSON-Array ausgeben.</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>No serial ports found (pseudo-terminals are not listed; give their path to --port).</source>
        <translation>Keine seriellen Schnittstellen gefunden (Pseudo-Terminals werden nicht aufgelistet; ihren Pfad bei --port angeben).</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>device now: %1</source>
        <translation>Gerätedatei jetzt: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>description: %1</source>
        <translation>Beschreibung: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>manufacturer: %1</source>
        <translation>Hersteller: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>serial number: %1</source>
        <translation>Seriennummer: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>USB id: %1:%2</source>
        <translation>USB-ID: %1:%2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>access: ok</source>
        <translation>Zugriff: ok</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>access: %1</source>
        <translation>Zugriff: %1</translation>
    </message>
</context>
<context>
    <name>jumo::PtyPair</name>
    <message>
        <location filename="../lib/sim/ptypair.cpp" line="+21"/>
        <source>cannot start socat (is it installed?): %1</source>
        <translation>socat kann nicht gestartet werden (ist es installiert?): %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>socat ended: %1</source>
        <translation>socat beendet: %1</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>socat did not create the pseudo-terminals</source>
        <translation>socat hat die Pseudo-Terminals nicht angelegt</translation>
    </message>
</context>
<context>
    <name>jumo::PublisherProgram</name>
    <message>
        <location filename="../lib/mqtt/publisherprogram.cpp" line="+36"/>
        <source>Publishes the devices of a station&apos;s lines to an MQTT broker: identity, values with their validity and status, alarm bits, line state. Owns the lines and only reads them.</source>
        <translation>Veröffentlicht die Geräte der Linien einer Station an einem MQTT-Broker: Identität, Werte mit Gültigkeit und Status, Alarmbits, Linienzustand. Ist Master der Linien und liest sie nur.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Broker (required): mqtt://[USER@]HOST[:PORT], or mqtts://... for TLS (port 8883).</source>
        <translation>Broker (erforderlich): mqtt://[BENUTZER@]HOST[:PORT], oder mqtts://... für TLS (Port 8883).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>url</source>
        <translation>URL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The station&apos;s name in the topics (default: the host name).</source>
        <translation>Name der Station in den Topics (Standard: der Hostname).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>station</source>
        <translation>Station</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First topic level(s) (default jumo).</source>
        <translation>Erste Topic-Ebene(n) (Standard jumo).</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>prefix</source>
        <translation>Präfix</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>User name at the broker (instead of the one in --broker).</source>
        <translation>Benutzername am Broker (statt dem in --broker).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>user</source>
        <translation>Benutzer</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>File whose first line is the broker password (else JUMO_MQTT_PASSWORD; never on the command line, where every user could read it).</source>
        <translation>Datei, deren erste Zeile das Broker-Passwort ist (sonst JUMO_MQTT_PASSWORD; nie auf der Befehlszeile, wo jeder Benutzer es lesen könnte).</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+3"/>
        <location line="+1"/>
        <location line="+1"/>
        <location line="+2"/>
        <source>file</source>
        <translation>Datei</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>TLS: the CA certificate that signed the broker&apos;s (default: the system&apos;s).</source>
        <translation>TLS: das CA-Zertifikat, das das des Brokers signiert hat (Standard: die des Systems).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>TLS: a client certificate (with --tls-key).</source>
        <translation>TLS: ein Client-Zertifikat (mit --tls-key).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>TLS: the client certificate&apos;s key.</source>
        <translation>TLS: der Schlüssel des Client-Zertifikats.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Station file (JSON: its name, lines and devices; see README, &apos;Station files&apos;).</source>
        <translation>Stationsdatei (JSON: Name, Linien und Geräte; siehe README, &apos;Station files&apos;).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>A line: ADDRESS[,name=NAME][,baud=N][,format=8N1][,timeout=MS][,min-response=MS][,retries=N] (repeat for more lines).</source>
        <translation>Eine Linie: ADRESSE[,name=NAME][,baud=N][,format=8N1][,timeout=MS][,min-response=MS][,retries=N] (für weitere Linien wiederholen).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>spec</source>
        <translation>Angabe</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial port of a station of one line (instead of --line).</source>
        <translation>Serielle Schnittstelle einer Station mit einer Linie (statt --line).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>path</source>
        <translation>Pfad</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Baud rate of --port and of --line specs without one: 4800, 9600, 19200 or 38400 (default 9600).</source>
        <translation>Baudrate von --port und von --line-Angaben ohne eigene: 4800, 9600, 19200 oder 38400 (Standard 9600).</translation>
    </message>
    <message>
        <location line="+1"/>
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
        <location line="+2"/>
        <source>Retries after a lost reply (default 2).</source>
        <translation>Wiederholungen nach einer ausgebliebenen Antwort (Standard 2).</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>A device, FAMILY@ADDRESS, or LINE/FAMILY@ADDRESS with several lines (repeat for more).</source>
        <translation>Ein Gerät, FAMILIE@ADRESSE, oder LINIE/FAMILIE@ADRESSE bei mehreren Linien (für weitere wiederholen).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>What the devices of a family poll and publish, instead of every readable entry: FAMILY:ENTRY[,ENTRY...], where &apos;faceplate&apos; stands for what the overview faceplate shows and &apos;alarms&apos; for every bit field with alarm bits (repeat for more families).</source>
        <translation>Was die Geräte einer Familie abfragen und veröffentlichen, statt jedes lesbaren Eintrags: FAMILIE:EINTRAG[,EINTRAG...], wobei &apos;faceplate&apos; für das steht, was die Kachel der Übersicht zeigt, und &apos;alarms&apos; für jedes Bitfeld mit Alarmbits (für weitere Familien wiederholen).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>family:entries</source>
        <translation>familie:einträge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heartbeat interval in ms (default 1000).</source>
        <translation>Heartbeat-Intervall in ms (Standard 1000).</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start even when a station of this name is online at the broker: that publisher stops (without it, this one refuses to start, exit code 2).</source>
        <translation>Auch starten, wenn eine Station dieses Namens am Broker online ist: dieser Publisher stoppt dann (ohne die Option verweigert dieser den Start, Exit-Code 2).</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>unexpected argument &apos;%1&apos;</source>
        <translation>unerwartetes Argument &apos;%1&apos;</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--broker is required, e.g. --broker mqtt://localhost</source>
        <translation>--broker ist erforderlich, z. B. --broker mqtt://localhost</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>&apos;%1&apos; cannot be a topic prefix: one or more levels joined by &apos;/&apos;, without &apos;+&apos;, &apos;#&apos; or control characters, not starting with &apos;$&apos;</source>
        <translation>&apos;%1&apos; kann kein Topic-Präfix sein: eine oder mehrere durch &apos;/&apos; verbundene Ebenen, ohne &apos;+&apos;, &apos;#&apos; oder Steuerzeichen, nicht mit &apos;$&apos; beginnend</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>--heartbeat must be 100..60000 ms</source>
        <translation>--heartbeat muss 100..60000 ms sein</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>give the lines by one of --station FILE, --line SPEC (once per line) or --port PATH</source>
        <translation>die Linien mit genau einem von --station DATEI, --line ANGABE (einmal je Linie) oder --port PFAD angeben</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unsupported baud rate or data format: %1 %2</source>
        <translation>Baudrate oder Datenformat nicht unterstützt: %1 %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--retries must be 0..10</source>
        <translation>--retries muss 0..10 sein</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>refused map file: %1</source>
        <translation>Map-Datei abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--poll %1: %2</source>
        <translation>--poll %1: %2</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>--poll names %1 twice: give its entries in one</source>
        <translation>--poll nennt %1 zweimal: ihre Einträge in einem angeben</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a station file lists its devices: --device goes with --line or --port</source>
        <translation>eine Stationsdatei nennt ihre Geräte selbst: --device gehört zu --line oder --port</translation>
    </message>
    <message>
        <location line="+35"/>
        <source>%1 is named twice</source>
        <translation>%1 ist doppelt genannt</translation>
    </message>
    <message>
        <location line="+15"/>
        <source>--poll %1: no device of the station is a %1</source>
        <translation>--poll %1: kein Gerät der Station ist ein %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>name at least one device: --device FAMILY@ADDRESS (LINE/FAMILY@ADDRESS with several lines)</source>
        <translation>mindestens ein Gerät nennen: --device FAMILIE@ADRESSE (LINIE/FAMILIE@ADRESSE bei mehreren Linien)</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;%1&apos; cannot be a station name: it is one topic level, without &apos;/&apos;, &apos;+&apos; and &apos;#&apos;</source>
        <translation>&apos;%1&apos; kann kein Stationsname sein: er ist eine Topic-Ebene, ohne &apos;/&apos;, &apos;+&apos; und &apos;#&apos;</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>another publisher took over station %1 (--take-over): stopped</source>
        <translation>ein anderer Publisher hat die Station %1 übernommen (--take-over): gestoppt</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>a station named %1 is online at %2: give this one another --name, or --take-over to replace it</source>
        <translation>eine Station namens %1 ist an %2 online: geben Sie dieser einen anderen --name oder --take-over, um jene zu ersetzen</translation>
    </message>
</context>
<context>
    <name>jumo::ReadPlanner</name>
    <message>
        <location filename="../lib/bus/devicepoll.cpp" line="+89"/>
        <location filename="../lib/protocol/readplanner.cpp" line="+32"/>
        <source>&apos;%1&apos; is not an entry of %2</source>
        <translation>&apos;%1&apos; ist kein Eintrag von %2</translation>
    </message>
    <message>
        <location filename="../lib/protocol/readplanner.cpp" line="+49"/>
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
        <location filename="../lib/protocol/registermap.cpp" line="+296"/>
        <source>the gateway&apos;s path to the device is unavailable (sent by the gateway, the request did not reach the device)</source>
        <translation>der Weg des Gateways zum Gerät ist nicht verfügbar (vom Gateway gesendet, die Anfrage hat das Gerät nicht erreicht)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the device behind the gateway did not respond (sent by the gateway)</source>
        <translation>das Gerät hinter dem Gateway hat nicht geantwortet (vom Gateway gesendet)</translation>
    </message>
    <message>
        <location line="+3"/>
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
        <location filename="../lib/models/registermapmodel.cpp" line="+36"/>
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
    <name>jumo::RegularFile</name>
    <message>
        <location filename="../lib/protocol/regularfile.cpp" line="+49"/>
        <source>%1: not a regular file</source>
        <translation>%1: keine reguläre Datei</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>%1: too big (%2 bytes, at most %3)</source>
        <translation>%1: zu groß (%2 Bytes, höchstens %3)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: too big (more than %2 bytes)</source>
        <translation>%1: zu groß (mehr als %2 Bytes)</translation>
    </message>
</context>
<context>
    <name>jumo::RemoteLines</name>
    <message>
        <location filename="../lib/mqtt/remotelines.cpp" line="+251"/>
        <source>the station has not reported this line</source>
        <translation>die Station hat diese Leitung nicht gemeldet</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the broker cannot be reached: values are the last ones received</source>
        <translation>der Broker ist nicht erreichbar: die Werte sind die zuletzt empfangenen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>station %1 has not said that it is online</source>
        <translation>Station %1 hat nicht gemeldet, dass sie online ist</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>station %1 was stopped</source>
        <translation>Station %1 wurde beendet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>station %1 is offline (%2)</source>
        <translation>Station %1 ist offline (%2)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>station %1 has not been heard for %2 s</source>
        <translation>von Station %1 kam seit %2 s nichts</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>receiving the state of station %1</source>
        <translation>der Zustand der Station %1 wird empfangen</translation>
    </message>
</context>
<context>
    <name>jumo::RemoteStation</name>
    <message>
        <location filename="../lib/mqtt/remotestation.cpp" line="+47"/>
        <source>a message of %1 bytes, over the limit of %2</source>
        <translation>eine Nachricht von %1 Byte, über der Grenze von %2</translation>
    </message>
    <message>
        <location line="+170"/>
        <source>more than %1 stations publish under %2/: use --remote-station NAME</source>
        <translation>mehr als %1 Stationen veröffentlichen unter %2/: --remote-station NAME verwenden</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>not a station status</source>
        <translation>kein Stationsstatus</translation>
    </message>
    <message>
        <location line="+86"/>
        <source>not a device order</source>
        <translation>keine Gerätereihenfolge</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>not a line state</source>
        <translation>kein Leitungszustand</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>more than %1 lines in one station</source>
        <translation>mehr als %1 Leitungen in einer Station</translation>
    </message>
    <message>
        <location line="+36"/>
        <location line="+54"/>
        <source>its info does not name this device</source>
        <translation>ihre Info nennt dieses Gerät nicht</translation>
    </message>
    <message>
        <location line="-48"/>
        <source>more than %1 devices in one station</source>
        <translation>mehr als %1 Geräte in einer Station</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>no info for this device, and too much waiting for one</source>
        <translation>keine Info für dieses Gerät, und zu viel wartet auf eine</translation>
    </message>
    <message>
        <location line="+47"/>
        <source>not a device condition</source>
        <translation>kein Gerätezustand</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>no entry of %1</source>
        <translation>kein Eintrag von %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not a value (or its validity and status disagree)</source>
        <translation>kein Wert (oder seine Gültigkeit und sein Status widersprechen sich)</translation>
    </message>
</context>
<context>
    <name>jumo::RemoteWindow</name>
    <message>
        <location filename="../ui/remotewindow.cpp" line="+48"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Register</source>
        <translation>Register</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Bit</source>
        <translation>Bit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Id</source>
        <translation>Id</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Signal</source>
        <translation>Signal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Kind</source>
        <translation>Art</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>State</source>
        <translation>Zustand</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>JUMO HMI remote view: %1 [read-only]</source>
        <translation>JUMO HMI Fernansicht: %1 [nur lesen]</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Overview</source>
        <translation>Übersicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Alarm journal (this viewer)</source>
        <translation>Alarmjournal (dieser Ansicht)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Remote view: values as the stations publish them to the broker. Nothing can be written from here.</source>
        <translation>Fernansicht: Werte, wie die Stationen sie an den Broker senden. Von hier aus kann nichts geschrieben werden.</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Compact overview</source>
        <translation>&amp;Kompakte Übersicht</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Not shown: %1 (%2)</source>
        <translation>Nicht angezeigt: %1 (%2)</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>Connected</source>
        <translation>Verbunden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Line lost</source>
        <translation>Leitung verloren</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+49"/>
        <source>line lost</source>
        <translation>Leitung verloren</translation>
    </message>
    <message>
        <location line="-47"/>
        <source>Line lost: %1</source>
        <translation>Leitung verloren: %1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Disconnected: %1</source>
        <translation>Getrennt: %1</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>connected</source>
        <translation>verbunden</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>disconnected</source>
        <translation>getrennt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <location line="+128"/>
        <source>This broker lets anyone publish station data: values and liveness may be forged.</source>
        <translation>Dieser Broker lässt jeden Stationsdaten veröffentlichen: Werte und Lebenszeichen können gefälscht sein.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>This viewer&apos;s own user could publish into a station&apos;s topics; give the broker users and an ACL (README, &quot;MQTT&quot;).</source>
        <translation>Der eigene Benutzer dieses Betrachters könnte in die Topics einer Station veröffentlichen; richten Sie am Broker Benutzer und eine ACL ein (README, &quot;MQTT&quot;).</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>Broker %1: connected</source>
        <translation>Broker %1: verbunden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Broker %1: connecting</source>
        <translation>Broker %1: Verbindung wird aufgebaut</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Broker %1: not reachable (%2); values are the last ones received</source>
        <translation>Broker %1: nicht erreichbar (%2); die Werte sind die zuletzt empfangenen</translation>
    </message>
    <message numerus="yes">
        <location line="+19"/>
        <source>%1 undid %n message(s) of other clients</source>
        <translation>
            <numerusform>%1 hat %n Nachricht anderer Clients rückgängig gemacht</numerusform>
            <numerusform>%1 hat %n Nachrichten anderer Clients rückgängig gemacht</numerusform>
        </translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Live: %1</source>
        <translation>Aktiv: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Online, receiving its state: %1</source>
        <translation>Online, empfängt seinen Zustand: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not live: %1</source>
        <translation>Nicht aktiv: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No station heard yet</source>
        <translation>Noch keine Station gehört</translation>
    </message>
</context>
<context>
    <name>jumo::ReportDetailsDialog</name>
    <message>
        <location filename="../ui/reportdetailsdialog.cpp" line="+22"/>
        <source>Commissioning report</source>
        <translation>Inbetriebnahmebericht</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Plant, hall or building</source>
        <translation>Anlage, Halle oder Gebäude</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cabinet or panel</source>
        <translation>Schaltschrank oder Tafel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>e.g. TIC-101</source>
        <translation>z. B. TIC-101</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Who commissions the device</source>
        <translation>Wer das Gerät in Betrieb nimmt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Choose a &amp;file...</source>
        <translation>&amp;Datei wählen...</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The title block of the report of %1. What you enter here is offered again next time.</source>
        <translation>Die Kopfdaten des Berichts von %1. Was Sie hier eingeben, wird beim nächsten Mal wieder angeboten.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&amp;Site:</source>
        <translation>Stand&amp;ort:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Cabinet:</source>
        <translation>&amp;Schaltschrank:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device &amp;tag:</source>
        <translation>Geräte&amp;kennzeichen:</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Engineer:</source>
        <translation>&amp;Inbetriebnehmer:</translation>
    </message>
</context>
<context>
    <name>jumo::ReportWriter</name>
    <message>
        <location filename="../ui/reportwriter.cpp" line="+169"/>
        <source>Page %1 of %2</source>
        <translation>Seite %1 von %2</translation>
    </message>
</context>
<context>
    <name>jumo::RtuStreamFramer</name>
    <message>
        <location filename="../lib/bus/rtustreamframer.cpp" line="+64"/>
        <source>no reply within %1 ms</source>
        <translation>keine Antwort innerhalb von %1 ms</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>no reply that fits the request within %1 ms (%n that did not fit dropped)</source>
        <translation>
            <numerusform>keine zur Anfrage passende Antwort innerhalb von %1 ms (%n unpassende verworfen)</numerusform>
            <numerusform>keine zur Anfrage passende Antwort innerhalb von %1 ms (%n unpassende verworfen)</numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>no complete reply within %1 ms (%2 byte(s) received: %3)</source>
        <translation>keine vollständige Antwort innerhalb von %1 ms (%2 Byte empfangen: %3)</translation>
    </message>
</context>
<context>
    <name>jumo::RtuTcpTransport</name>
    <message>
        <location filename="../lib/bus/rtutcptransport.cpp" line="+55"/>
        <source>not sent: the line was never silent for %1 ms within %2 ms (noise or another master on the serial side?)</source>
        <translation>nicht gesendet: die Leitung war innerhalb von %2 ms nie %1 ms lang still (Störungen oder ein anderer Master auf der seriellen Seite?)</translation>
    </message>
    <message numerus="yes">
        <location line="+37"/>
        <source>%n frame(s) before the reply that answer another request</source>
        <translation>
            <numerusform>%n Rahmen vor der Antwort, der eine andere Anfrage beantwortet</numerusform>
            <numerusform>%n Rahmen vor der Antwort, die eine andere Anfrage beantworten</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>jumo::RtuTransport</name>
    <message>
        <location filename="../lib/bus/rtutransport.cpp" line="+26"/>
        <source>the port %1</source>
        <translation>die Schnittstelle %1</translation>
    </message>
    <message>
        <location line="+128"/>
        <source>reply with function code %1 to a request with %2</source>
        <translation>Antwort mit Funktionscode %1 auf eine Anfrage mit %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>reply of %1 words where %2 were asked for</source>
        <translation>Antwort mit %1 Wörtern, angefragt waren %2</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>write reply names %1 word(s) at %2 where %3 at %4 were written</source>
        <translation>Schreibantwort nennt %1 Wort/Wörter ab %2, geschrieben wurden %3 ab %4</translation>
    </message>
    <message>
        <location line="+36"/>
        <source>no reply</source>
        <translation>keine Antwort</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>exception %1</source>
        <translation>Exception %1</translation>
    </message>
</context>
<context>
    <name>jumo::ScanDialog</name>
    <message>
        <location filename="../ui/scandialog.cpp" line="+23"/>
        <source>Scan</source>
        <translation>Suchen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cancel scan</source>
        <translation>Suche abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Thorough: every address at the full timeout (slow)</source>
        <translation>&amp;Gründlich: jede Adresse mit der vollen Zeitüberschreitung (langsam)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Scan the line</source>
        <translation>Leitung durchsuchen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>A quick scan gives each address a short timeout and probes again at the full timeout wherever it heard anything, which finds devices that answer late too. A thorough scan probes every address twice at the full timeout: minutes for the whole range.</source>
        <translation>Eine schnelle Suche gibt jeder Adresse eine kurze Zeitüberschreitung und fragt überall dort erneut mit der vollen ab, wo sie etwas gehört hat; so findet sie auch Geräte, die spät antworten. Eine gründliche Suche fragt jede Adresse zweimal mit der vollen Zeitüberschreitung ab: Minuten für den ganzen Bereich.</translation>
    </message>
    <message numerus="yes">
        <location line="+16"/>
        <source>address %1, about %n s left</source>
        <translation>
            <numerusform>Adresse %1, noch etwa %n s</numerusform>
            <numerusform>Adresse %1, noch etwa %n s</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Address %1 answers as %2, as every %2 does whatever its own address: not a device of its own</source>
        <translation>Adresse %1 antwortet als %2, wie jedes %2 unabhängig von seiner eigenen Adresse: kein eigenes Gerät</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>%1 at address %2</source>
        <translation>%1 an Adresse %2</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Unknown device at address %1</source>
        <translation>Unbekanntes Gerät an Adresse %1</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>cancelled</source>
        <translation>abgebrochen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>stopped: %1</source>
        <translation>angehalten: %1</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n device(s) found in %1 s</source>
        <translation>
            <numerusform>%n Gerät in %1 s gefunden</numerusform>
            <numerusform>%n Geräte in %1 s gefunden</numerusform>
        </translation>
    </message>
    <message>
        <location line="+41"/>
        <source>Each address is probed once at %1 ms, again at the full %2 ms where anything was heard.</source>
        <translation>Jede Adresse wird einmal mit %1 ms abgefragt, erneut mit den vollen %2 ms, wo etwas gehört wurde.</translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>The range is short: %n address(es) next to it are probed once first, to hear late answers, and not reported.</source>
        <translation>
            <numerusform>Der Bereich ist kurz: %n Adresse daneben wird zuerst einmal abgefragt, um späte Antworten zu hören, und nicht gemeldet.</numerusform>
            <numerusform>Der Bereich ist kurz: %n Adressen daneben werden zuerst einmal abgefragt, um späte Antworten zu hören, und nicht gemeldet.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+7"/>
        <source>Every address is probed at the full timeout of %1 ms: up to %n s.</source>
        <translation>
            <numerusform>Jede Adresse wird mit der vollen Zeitüberschreitung von %1 ms abgefragt: bis zu %n s.</numerusform>
            <numerusform>Jede Adresse wird mit der vollen Zeitüberschreitung von %1 ms abgefragt: bis zu %n s.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+21"/>
        <source>probing %n address(es) next to the range first</source>
        <translation>
            <numerusform>zuerst wird %n Adresse neben dem Bereich abgefragt</numerusform>
            <numerusform>zuerst werden %n Adressen neben dem Bereich abgefragt</numerusform>
        </translation>
    </message>
    <message>
        <location line="-68"/>
        <source>From address</source>
        <translation>Von Adresse</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>to</source>
        <translation>bis</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Add checked devices</source>
        <translation>Markierte Geräte hinzufügen</translation>
    </message>
</context>
<context>
    <name>jumo::SerialPortList</name>
    <message>
        <location filename="../lib/bus/serialportlist.cpp" line="+83"/>
        <source>serial number %1</source>
        <translation>Seriennummer %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
</context>
<context>
    <name>jumo::Signals</name>
    <message>
        <location filename="../app/cli/quitonsignal.cpp" line="+74"/>
        <source>terminated: %1</source>
        <translation>beendet: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>hangup: %1</source>
        <translation>Verbindung beendet (SIGHUP): %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>output closed: %1</source>
        <translation>Ausgabe geschlossen: %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>interrupted: %1</source>
        <translation>abgebrochen: %1</translation>
    </message>
</context>
<context>
    <name>jumo::SocketTransport</name>
    <message>
        <location filename="../lib/bus/sockettransport.cpp" line="+34"/>
        <source>the gateway %1</source>
        <translation>das Gateway %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device server %1</source>
        <translation>der Geräteserver %1</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>the gateway %1 closed the connection</source>
        <translation>das Gateway %1 hat die Verbindung geschlossen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the device server %1 closed the connection</source>
        <translation>der Geräteserver %1 hat die Verbindung geschlossen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the connection was refused or closed</source>
        <translation>die Verbindung wurde abgelehnt oder geschlossen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>connection to the gateway %1 lost: %2</source>
        <translation>Verbindung zum Gateway %1 verloren: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>connection to the device server %1 lost: %2</source>
        <translation>Verbindung zum Geräteserver %1 verloren: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>no connection to the gateway %1: %2</source>
        <translation>keine Verbindung zum Gateway %1: %2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no connection to the device server %1: %2</source>
        <translation>keine Verbindung zum Geräteserver %1: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the gateway %1 did not accept a connection within %2 s</source>
        <translation>das Gateway %1 hat innerhalb von %2 s keine Verbindung angenommen</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the device server %1 did not accept a connection within %2 s</source>
        <translation>der Geräteserver %1 hat innerhalb von %2 s keine Verbindung angenommen</translation>
    </message>
</context>
<context>
    <name>jumo::StationCommands</name>
    <message>
        <location filename="../app/cli/stationcommands.cpp" line="+18"/>
        <source>Checks a station file and lists its lines and devices as the line commands take them (--station FILE). Every problem is named with the line and the key; no line is opened.</source>
        <translation>Prüft eine Stationsdatei und listet ihre Leitungen und Geräte so auf, wie die Leitungsbefehle sie nehmen (--station FILE). Jedes Problem wird mit Leitung und Schlüssel genannt; keine Leitung wird geöffnet.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Only check: one line of summary when the file is good.</source>
        <translation>Nur prüfen: eine Zeile Zusammenfassung, wenn die Datei in Ordnung ist.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Print the station as its file would be written, every default filled in.</source>
        <translation>Die Station so ausgeben, wie ihre Datei geschrieben würde, mit allen Vorgaben ausgefüllt.</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Station file (JSON).</source>
        <translation>Stationsdatei (JSON).</translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n line(s)</source>
        <translation>
            <numerusform>%n Leitung</numerusform>
            <numerusform>%n Leitungen</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n device(s)</source>
        <translation>
            <numerusform>%n Gerät</numerusform>
            <numerusform>%n Geräte</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: a good station file (%2)</source>
        <translation>%1: eine gültige Stationsdatei (%2)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>station %1: %2</source>
        <translation>Station %1: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>timeout %1 ms</source>
        <translation>Timeout %1 ms</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>timeout from the families</source>
        <translation>Timeout aus den Gerätefamilien</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>minimum response %1 ms</source>
        <translation>minimale Antwortzeit %1 ms</translation>
    </message>
    <message numerus="yes">
        <location line="+1"/>
        <source>%n retry(s)</source>
        <translation>
            <numerusform>%n Wiederholung</numerusform>
            <numerusform>%n Wiederholungen</numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read-only</source>
        <translation>schreibgeschützt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>line %1: %2 (%3)</source>
        <translation>Leitung %1: %2 (%3)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no devices listed</source>
        <translation>keine Geräte aufgeführt</translation>
    </message>
</context>
<context>
    <name>jumo::StationConfig</name>
    <message>
        <location filename="../lib/bus/stationconfig.cpp" line="+48"/>
        <source>the line address (serial port or URL) is empty</source>
        <translation>die Adresse der Leitung (serielle Schnittstelle oder URL) ist leer</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+148"/>
        <source>&apos;name&apos; must be 1..%1 of the letters A-Z, a-z, digits, &apos;_&apos;, &apos;.&apos; and &apos;-&apos;, not &apos;%2&apos;</source>
        <translation>&apos;name&apos; muss aus 1..%1 der Zeichen A-Z, a-z, Ziffern, &apos;_&apos;, &apos;.&apos; und &apos;-&apos; bestehen, nicht &apos;%2&apos;</translation>
    </message>
    <message>
        <location line="-141"/>
        <source>&apos;%1&apos; must be 4800, 9600, 19200 or 38400, not %2</source>
        <translation>&apos;%1&apos; muss 4800, 9600, 19200 oder 38400 sein, nicht %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; must be 8N1, 8E1, 8O1 or 8N2, not %2</source>
        <translation>&apos;%1&apos; muss 8N1, 8E1, 8O1 oder 8N2 sein, nicht %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; must be 0 (derived from the baud rate and the families) or 10..60000 ms, not %2</source>
        <translation>&apos;%1&apos; muss 0 (aus Baudrate und Gerätefamilien abgeleitet) oder 10..60000 ms sein, nicht %2</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>address %1 is used twice on the line (%2)</source>
        <translation>Adresse %1 ist auf der Leitung doppelt vergeben (%2)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>the line name &apos;%1&apos; is used by lines[%2] too</source>
        <translation>der Leitungsname &apos;%1&apos; wird auch von lines[%2] verwendet</translation>
    </message>
    <message>
        <location line="+32"/>
        <source>&apos;port&apos; %1 is the port of lines[%2] (%3) too: a line has one master, so give the devices of both to one line</source>
        <translation>&apos;port&apos; %1 ist auch der Anschluss von lines[%2] (%3): eine Leitung hat einen Master, daher die Geräte beider einer Leitung geben</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>malformed JSON at byte %1: %2</source>
        <translation>fehlerhaftes JSON bei Byte %1: %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>malformed JSON at byte %1: a control character</source>
        <translation>fehlerhaftes JSON bei Byte %1: ein Steuerzeichen</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>malformed JSON at byte %1: &apos;%2&apos; given twice in one object</source>
        <translation>fehlerhaftes JSON bei Byte %1: &apos;%2&apos; steht zweimal in einem Objekt</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>not a station file (no &quot;format&quot;: &quot;jumo-station&quot;)</source>
        <translation>keine Stationsdatei (kein &quot;format&quot;: &quot;jumo-station&quot;)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>station file version %1 is not supported (expected %2)</source>
        <translation>Stationsdatei-Version %1 wird nicht unterstützt (erwartet: %2)</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>&apos;lines&apos; must be an array of lines</source>
        <translation>&apos;lines&apos; muss ein Array von Leitungen sein</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>a line must be an object, not %1</source>
        <translation>eine Leitung muss ein Objekt sein, nicht %1</translation>
    </message>
    <message>
        <location line="+42"/>
        <source>&apos;devices&apos; must be an array of &quot;FAMILY@ADDRESS&quot; texts, e.g. &quot;ipc300@1&quot;</source>
        <translation>&apos;devices&apos; muss ein Array von Texten &quot;FAMILY@ADDRESS&quot; sein, z. B. &quot;ipc300@1&quot;</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>&apos;%1&apos; is not a device: use FAMILY@ADDRESS, e.g. ipc300@1</source>
        <translation>&apos;%1&apos; ist kein Gerät: FAMILY@ADDRESS verwenden, z. B. ipc300@1</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos;: unknown family &apos;%2&apos; (families: %3)</source>
        <translation>&apos;%1&apos;: unbekannte Gerätefamilie &apos;%2&apos; (Gerätefamilien: %3)</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;%1&apos;: the address must be 1..%2, not %3</source>
        <translation>&apos;%1&apos;: die Adresse muss 1..%2 sein, nicht %3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos;: a %2 cannot have address %3, its addresses are %4..%5</source>
        <translation>&apos;%1&apos;: ein %2 kann nicht die Adresse %3 haben, seine Adressen sind %4..%5</translation>
    </message>
    <message>
        <location line="+116"/>
        <source>&apos;%1&apos; must be a whole number %2..%3, not &apos;%4&apos;</source>
        <translation>&apos;%1&apos; muss eine ganze Zahl %2..%3 sein, nicht &apos;%4&apos;</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>&apos;%1&apos; is given twice</source>
        <translation>&apos;%1&apos; ist zweimal angegeben</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;read-only&apos; takes no value</source>
        <translation>&apos;read-only&apos; nimmt keinen Wert</translation>
    </message>
    <message>
        <location line="+30"/>
        <source>unknown option &apos;%1&apos; (ADDRESS[,name=NAME][,baud=N][,format=8N1][,timeout=MS][,min-response=MS][,retries=N][,read-only])</source>
        <translation>unbekannte Option &apos;%1&apos; (ADDRESS[,name=NAME][,baud=N][,format=8N1][,timeout=MS][,min-response=MS][,retries=N][,read-only])</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>--line &apos;%1&apos;: %2</source>
        <translation>--line &apos;%1&apos;: %2</translation>
    </message>
    <message>
        <location line="+56"/>
        <source>&apos;%1&apos;: there is no line &apos;%2&apos; (lines: %3)</source>
        <translation>&apos;%1&apos;: es gibt keine Leitung &apos;%2&apos; (Leitungen: %3)</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos;: no line is given</source>
        <translation>&apos;%1&apos;: keine Leitung angegeben</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&apos;%1&apos;: which line? The station has the lines %2: name it as LINE/%1, e.g. %3/%1</source>
        <translation>&apos;%1&apos;: welche Leitung? Die Station hat die Leitungen %2: als LINE/%1 angeben, z. B. %3/%1</translation>
    </message>
</context>
<context>
    <name>jumo::StationLine</name>
    <message>
        <location filename="../ui/stationline.cpp" line="-4"/>
        <source>Connected</source>
        <translation>Verbunden</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Line lost since %1</source>
        <translation>Leitung verloren seit %1</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Line lost since %1: %2</source>
        <translation>Leitung verloren seit %1: %2</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Disconnected</source>
        <translation>Getrennt</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Disconnected: %1</source>
        <translation>Getrennt: %1</translation>
    </message>
</context>
<context>
    <name>jumo::SystemSettings</name>
    <message>
        <location filename="../app/cli/systemsettings.cpp" line="+48"/>
        <location line="+11"/>
        <source>%1 cannot be read (%2): read-only mode is on until it can</source>
        <translation>%1 kann nicht gelesen werden (%2): der Nur-Lese-Modus gilt, bis die Datei gelesen werden kann</translation>
    </message>
    <message>
        <location line="-10"/>
        <source>it is a folder</source>
        <translation>es ist ein Ordner</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a link to nothing</source>
        <translation>ein Verweis ins Leere</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>it is no regular file</source>
        <translation>es ist keine reguläre Datei</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no permission</source>
        <translation>keine Berechtigung</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>malformed</source>
        <translation>fehlerhaft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>access error</source>
        <translation>Zugriffsfehler</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>%1: &apos;%2&apos; is taken as readOnly</source>
        <translation>%1: &apos;%2&apos; wird als readOnly genommen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: &apos;%2=%3&apos; is no true or false: read-only mode is on</source>
        <translation>%1: &apos;%2=%3&apos; ist weder true noch false: der Nur-Lese-Modus ist an</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1: unknown key &apos;%2&apos; (known: %3)</source>
        <translation>%1: unbekannter Schlüssel &apos;%2&apos; (bekannt: %3)</translation>
    </message>
</context>
<context>
    <name>jumo::TcpTransport</name>
    <message>
        <location filename="../lib/bus/tcptransport.cpp" line="+20"/>
        <source>broadcasts are not sent through a Modbus TCP gateway</source>
        <translation>über ein Modbus-TCP-Gateway werden keine Broadcasts gesendet</translation>
    </message>
</context>
<context>
    <name>jumo::Theme</name>
    <message>
        <location filename="../ui/theme.cpp" line="+309"/>
        <source>&amp;System</source>
        <translation>&amp;System</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Light</source>
        <translation>&amp;Hell</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Dark</source>
        <translation>&amp;Dunkel</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;High contrast</source>
        <translation>Hoher &amp;Kontrast</translation>
    </message>
</context>
<context>
    <name>jumo::TrafficView</name>
    <message>
        <location filename="../ui/trafficview.cpp" line="+28"/>
        <source>Device</source>
        <translation>Gerät</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Requests</source>
        <translation>Anfragen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Timeouts</source>
        <translation>Zeitüberschreitungen</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CRC errors</source>
        <translation>CRC-Fehler</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Line</source>
        <translation>Leitung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mismatches</source>
        <translation>Unpassende Antworten</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Exceptions</source>
        <translation>Exceptions</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Last round trip</source>
        <translation>Letzte Umlaufzeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mean round trip</source>
        <translation>Mittlere Umlaufzeit</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Last cycle</source>
        <translation>Letzter Zyklus</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>(no reply)</source>
        <translation>(keine Antwort)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>  %1 ms</source>
        <translation>  %1 ms</translation>
    </message>
    <message>
        <location line="+28"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>%1 ms</source>
        <translation>%1 ms</translation>
    </message>
</context>
<context>
    <name>jumo::TrendView</name>
    <message>
        <location filename="../ui/trendview.cpp" line="+54"/>
        <source>1 minute</source>
        <translation>1 Minute</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5 minutes</source>
        <translation>5 Minuten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>15 minutes</source>
        <translation>15 Minuten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 hour</source>
        <translation>1 Stunde</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Export CSV...</source>
        <translation>CSV exportieren...</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+3"/>
        <source>Export trend</source>
        <translation>Trend exportieren</translation>
    </message>
    <message>
        <location line="-3"/>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <location line="+67"/>
        <source>Value (no unit)</source>
        <translation>Wert (ohne Einheit)</translation>
    </message>
</context>
<context>
    <name>jumo::ValueCodec</name>
    <message>
        <location filename="../lib/protocol/valuecodec.cpp" line="+96"/>
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
        <location line="+46"/>
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
    <name>jumo::ValueFormat</name>
    <message>
        <location filename="../lib/protocol/valueformat.cpp" line="+75"/>
        <source>%1 (none set)</source>
        <translation>%1 (keines gesetzt)</translation>
    </message>
</context>
<context>
    <name>jumo::ValueText</name>
    <message>
        <location filename="../lib/bus/valuetext.cpp" line="+29"/>
        <source>(configured)</source>
        <translation>(konfiguriert)</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Unit as configured on the device: %1</source>
        <translation>Einheit wie am Gerät konfiguriert: %1</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Not read yet</source>
        <translation>Noch nicht gelesen</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No answer</source>
        <translation>Keine Antwort</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Exception %1: %2</source>
        <translation>Exception %1: %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reply did not fit the request</source>
        <translation>Antwort passte nicht zur Anfrage</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device not answering</source>
        <translation>Gerät antwortet nicht</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Line lost</source>
        <translation>Leitung verloren</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Line disconnected</source>
        <translation>Leitung getrennt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Not available on this device</source>
        <translation>Auf diesem Gerät nicht vorhanden</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Identity not confirmed yet</source>
        <translation>Identität noch nicht bestätigt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Another device answers at this address</source>
        <translation>An dieser Adresse antwortet ein anderes Gerät</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stale (%1 s old)</source>
        <translation>Veraltet (%1 s alt)</translation>
    </message>
</context>
<context>
    <name>jumo::WriteAssignment</name>
    <message>
        <location filename="../app/cli/writeassignment.cpp" line="+31"/>
        <source>&apos;%1&apos; is not ID=VALUE or ID.BIT=0|1</source>
        <translation>&apos;%1&apos; hat nicht die Form ID=VALUE oder ID.BIT=0|1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;%1&apos; is not an entry of %2</source>
        <translation>&apos;%1&apos; ist kein Eintrag von %2</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;%1&apos; is given both whole and by bits: give one or the other</source>
        <translation>&apos;%1&apos; ist sowohl ganz als auch bitweise angegeben: eines von beiden angeben</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&apos;%1&apos; is given twice</source>
        <translation>&apos;%1&apos; ist zweimal angegeben</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&apos;%1&apos;: a broadcast is not answered, so the bits it should keep cannot be read; write the whole word</source>
        <translation>&apos;%1&apos;: Ein Broadcast wird nicht beantwortet, daher können die Bits, die erhalten bleiben sollen, nicht gelesen werden; das ganze Wort schreiben</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>&apos;%1&apos; is not a bit state for &apos;%2&apos;: give 0, 1, on, off, true or false</source>
        <translation>&apos;%1&apos; ist kein Bitzustand für &apos;%2&apos;: 0, 1, on, off, true oder false angeben</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>&apos;%1&apos; is given twice, on and off</source>
        <translation>&apos;%1&apos; ist zweimal angegeben, ein und aus</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>send a command as %1=BIT, e.g. %1=%2; it is sent once</source>
        <translation>einen Befehl als %1=BIT senden, z. B. %1=%2; er wird einmal gesendet</translation>
    </message>
</context>
<context>
    <name>jumo::WriteCommand</name>
    <message>
        <location filename="../lib/models/writecommand.cpp" line="+27"/>
        <location line="+2"/>
        <source>confirmed by read-back: %1</source>
        <translation>durch Zurücklesen bestätigt: %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>written, but the device does not report %1</source>
        <translation>geschrieben, aber das Gerät meldet nicht %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>written, but the device reads back %1</source>
        <translation>geschrieben, aber das Gerät liest %1 zurück</translation>
    </message>
    <message>
        <location line="+38"/>
        <location line="+7"/>
        <source>Writing %1...</source>
        <translation>%1 wird geschrieben...</translation>
    </message>
</context>
<context>
    <name>jumo::WriteTransaction</name>
    <message>
        <location filename="../lib/bus/writetransaction.cpp" line="+88"/>
        <source>refused by the device: exception %1, %2</source>
        <translation>vom Gerät abgelehnt: Exception %1, %2</translation>
    </message>
    <message>
        <location line="+2"/>
        <source> (precondition: %1)</source>
        <translation> (Voraussetzung: %1)</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>not written: the line went down before the write</source>
        <translation>nicht geschrieben: Die Leitung fiel vor dem Schreiben aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not written: the state of the other bits could not be read (%1)</source>
        <translation>nicht geschrieben: Der Zustand der übrigen Bits konnte nicht gelesen werden (%1)</translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+76"/>
        <source>exception %1, %2</source>
        <translation>Exception %1, %2</translation>
    </message>
    <message>
        <location line="-61"/>
        <source>not written: the gateway could not reach the device (exception %1, %2); nothing was changed</source>
        <translation>nicht geschrieben: das Gateway konnte das Gerät nicht erreichen (Ausnahme %1, %2); nichts wurde geändert</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the gateway got no answer from the device (exception %1, %2): the write may or may not have reached it; it is not sent again, check the device</source>
        <translation>das Gateway hat vom Gerät keine Antwort erhalten (Ausnahme %1, %2): der Schreibvorgang hat es vielleicht erreicht, vielleicht nicht; er wird nicht wiederholt, prüfen Sie das Gerät</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the line was lost while the write was under way: its outcome is unknown, check the device</source>
        <translation>die Leitung ging während des Schreibens verloren: Das Ergebnis ist unbekannt, prüfen Sie das Gerät</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>an answer that does not fit the command (%1): it may or may not have been carried out; it is not sent again, check the device</source>
        <translation>eine Antwort, die nicht zum Befehl passt (%1): Er wurde vielleicht ausgeführt, vielleicht nicht; er wird nicht erneut gesendet, prüfen Sie das Gerät</translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>no fitting answer after %n attempt(s) (the last: %1): the device may or may not have taken the value, read it back</source>
        <translation>
            <numerusform>keine passende Antwort nach %n Versuch (die letzte: %1): Das Gerät hat den Wert vielleicht übernommen, vielleicht nicht, lesen Sie ihn zurück</numerusform>
            <numerusform>keine passende Antwort nach %n Versuchen (die letzte: %1): Das Gerät hat den Wert vielleicht übernommen, vielleicht nicht, lesen Sie ihn zurück</numerusform>
        </translation>
    </message>
    <message>
        <location line="+8"/>
        <source>no answer: the command may or may not have been carried out; it is not sent again, check the device</source>
        <translation>keine Antwort: Der Befehl wurde vielleicht ausgeführt, vielleicht nicht; er wird nicht erneut gesendet, prüfen Sie das Gerät</translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>no answer after %n attempt(s): the device may or may not have taken the value, read it back</source>
        <translation>
            <numerusform>keine Antwort nach %n Versuch: Das Gerät hat den Wert vielleicht übernommen, vielleicht nicht, lesen Sie ihn zurück</numerusform>
            <numerusform>keine Antwort nach %n Versuchen: Das Gerät hat den Wert vielleicht übernommen, vielleicht nicht, lesen Sie ihn zurück</numerusform>
        </translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the line went down</source>
        <translation>die Leitung fiel aus</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>broadcast sent, but the device at address %1 could not be read back: %2</source>
        <translation>Broadcast gesendet, aber das Gerät an Adresse %1 konnte nicht zurückgelesen werden: %2</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>written and acknowledged, but the read-back failed: %1</source>
        <translation>geschrieben und quittiert, aber das Zurücklesen schlug fehl: %1</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>broadcast sent; it cannot be read back</source>
        <translation>Broadcast gesendet; er kann nicht zurückgelesen werden</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>acknowledged by the device; it does not report these bits, so they cannot be read back</source>
        <translation>vom Gerät quittiert; es meldet diese Bits nicht, daher können sie nicht zurückgelesen werden</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>written (not read back)</source>
        <translation>geschrieben (nicht zurückgelesen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>acknowledged by the device; it cannot be read back</source>
        <translation>vom Gerät quittiert; kann nicht zurückgelesen werden</translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+10"/>
        <source>confirmed by read-back: %1</source>
        <translation>durch Zurücklesen bestätigt: %1</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>written, but the device does not report %1</source>
        <translation>geschrieben, aber das Gerät meldet nicht %1</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>written, but the device reads back %1</source>
        <translation>geschrieben, aber das Gerät liest %1 zurück</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>broadcast not taken by the device at address %1: it reads back %2</source>
        <translation>Broadcast vom Gerät an Adresse %1 nicht übernommen: Es liest %2 zurück</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>broadcast confirmed by read-back from every device</source>
        <translation>Broadcast durch Zurücklesen von jedem Gerät bestätigt</translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+5"/>
        <source>not written: %1</source>
        <translation>nicht geschrieben: %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no answer, and then %1: the outcome is unknown, check the device</source>
        <translation>keine Antwort, und dann %1: Das Ergebnis ist unbekannt, prüfen Sie das Gerät</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>written and acknowledged, but not read back: %1</source>
        <translation>geschrieben und quittiert, aber nicht zurückgelesen: %1</translation>
    </message>
    <message>
        <location line="+16"/>
        <source>broadcast confirmed by read-back from every remaining device</source>
        <translation>Broadcast durch Zurücklesen von jedem verbleibenden Gerät bestätigt</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>broadcast sent; no device is left to read it back from</source>
        <translation>Broadcast gesendet; kein Gerät ist mehr da, um ihn zurückzulesen</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the device was removed from the line</source>
        <translation>das Gerät wurde von der Leitung entfernt</translation>
    </message>
</context>
<context>
    <name>jumo::maps</name>
    <message>
        <location filename="mapstrings.cpp" line="+7"/>
        <source>Invalid function</source>
        <translation>Ungültige Funktion</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invalid parameter address or too many words are to be read or written</source>
        <translation>Ungültige Parameteradresse oder zu viele Wörter zum Lesen oder Schreiben</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write access to parameter denied</source>
        <translation>Schreibzugriff auf Parameter verweigert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the unit of the value the limit comparator watches, as configured on the device (the process value&apos;s by default)</source>
        <translation>die Einheit des Werts, den der Grenzwertkomparator überwacht, wie am Gerät konfiguriert (standardmäßig die des Istwerts)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>as the math formula is configured on the device (its inputs and scaling)</source>
        <translation>wie die Mathematikformel am Gerät konfiguriert ist (ihre Eingänge und Skalierung)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the process value&apos;s unit, set with the analog input&apos;s configuration on the device: °C or °F for a thermocouple or RTD, the scaled unit of a standard signal</source>
        <translation>die Einheit des Istwerts, mit der Konfiguration des Analogeingangs am Gerät eingestellt: °C oder °F bei Thermoelement oder Widerstandsthermometer, die skalierte Einheit bei einem Einheitssignal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>process value units per minute or per hour, as the ramp function is configured on the device</source>
        <translation>Istwerteinheiten pro Minute oder pro Stunde, wie die Rampenfunktion am Gerät konfiguriert ist</translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Program status</source>
        <translation>Programmstatus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.1 Process data</source>
        <translation>5.1 Prozessdaten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Program pause</source>
        <translation>Programmpause</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Basic status/Program stop</source>
        <translation>Grundstatus/Programmstopp</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Automatic mode</source>
        <translation>Automatikbetrieb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Program end signal</source>
        <translation>Programmendesignal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tolerance limit signal</source>
        <translation>Toleranzbandsignal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller status</source>
        <translation>Reglerstatus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manual mode</source>
        <translation>Handbetrieb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Autotuning active</source>
        <translation>Selbstoptimierung aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary outputs 1 – 10</source>
        <translation>Binärausgänge 1 – 10</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary output 1</source>
        <translation>Binärausgang 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary output 2</source>
        <translation>Binärausgang 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary output 3</source>
        <translation>Binärausgang 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary output 4</source>
        <translation>Binärausgang 4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary output 5</source>
        <translation>Binärausgang 5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary output 6</source>
        <translation>Binärausgang 6</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary output 7</source>
        <translation>Binärausgang 7</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary output 8</source>
        <translation>Binärausgang 8</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary output 9</source>
        <translation>Binärausgang 9</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary output 10</source>
        <translation>Binärausgang 10</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary inputs 1 – 6</source>
        <translation>Binäreingänge 1 – 6</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary input 1</source>
        <translation>Binäreingang 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary input 2</source>
        <translation>Binäreingang 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary input 3</source>
        <translation>Binäreingang 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary input 4</source>
        <translation>Binäreingang 4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary input 6</source>
        <translation>Binäreingang 6</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary input 5</source>
        <translation>Binäreingang 5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary input 8</source>
        <translation>Binäreingang 8</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary input 7</source>
        <translation>Binäreingang 7</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator</source>
        <translation>Grenzwertüberwachung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 1</source>
        <translation>Grenzwertüberwachung 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 2</source>
        <translation>Grenzwertüberwachung 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 3</source>
        <translation>Grenzwertüberwachung 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 4</source>
        <translation>Grenzwertüberwachung 4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contacts 1 – 4</source>
        <translation>Steuerkontakte 1 – 4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contact 1</source>
        <translation>Steuerkontakt 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contact 2</source>
        <translation>Steuerkontakt 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contact 3</source>
        <translation>Steuerkontakt 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contact 4</source>
        <translation>Steuerkontakt 4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary signals</source>
        <translation>Binärsignale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer 1</source>
        <translation>Timer 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer 2</source>
        <translation>Timer 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Logic formula 1</source>
        <translation>Logikformel 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Logic formula 2</source>
        <translation>Logikformel 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control of the binary outputs</source>
        <translation>Ansteuerung der Binärausgänge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output 1</source>
        <translation>Ausgang 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output 2</source>
        <translation>Ausgang 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output 3</source>
        <translation>Ausgang 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output 4</source>
        <translation>Ausgang 4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output 5</source>
        <translation>Ausgang 5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output 6</source>
        <translation>Ausgang 6</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output 7</source>
        <translation>Ausgang 7</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output 8</source>
        <translation>Ausgang 8</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output 9</source>
        <translation>Ausgang 9</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output 10</source>
        <translation>Ausgang 10</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Activation</source>
        <translation>Aktivierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Analog input 1 (mV)</source>
        <oldsource>Analog input 2</oldsource>
        <translation>Analogeingang 1 (mV)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Internal Pt100</source>
        <translation>Interner Pt100</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sampling cycle time</source>
        <translation>Abtastzykluszeit</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Math 1</source>
        <translation>Mathematik 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Math 2</source>
        <translation>Mathematik 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramp end value (W)</source>
        <translation>Rampenendwert (W)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Filtered process value</source>
        <translation>Gefilterter Istwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unfiltered process value</source>
        <translation>Ungefilterter Istwert</translation>
    </message>
    <message>
        <location line="-73"/>
        <source>Setpoint</source>
        <translation>Sollwert</translation>
    </message>
    <message>
        <location line="+74"/>
        <source>Output (displayed value)</source>
        <translation>Stellgrad (Anzeigewert)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output, heating</source>
        <translation>Stellgrad, Heizen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output, cooling</source>
        <translation>Stellgrad, Kühlen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control difference</source>
        <translation>Regelabweichung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Switching status, heating</source>
        <translation>Schaltzustand, Heizen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off (contact open)</source>
        <translation>Aus (Kontakt offen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>On (contact closed)</source>
        <translation>Ein (Kontakt geschlossen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Switching status, cooling</source>
        <translation>Schaltzustand, Kühlen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set number</source>
        <translation>Parametersatznummer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manual output</source>
        <translation>Hand-Stellgrad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment number</source>
        <translation>Segmentnummer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Number of segments</source>
        <translation>Anzahl Segmente</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Program setpoint</source>
        <translation>Programmsollwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Program run time</source>
        <translation>Programmlaufzeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Residual program time</source>
        <translation>Programmrestzeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment run time</source>
        <translation>Segmentlaufzeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Residual segment time</source>
        <translation>Segmentrestzeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer run time, timer 1</source>
        <translation>Timerlaufzeit, Timer 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer run time, timer 2</source>
        <translation>Timerlaufzeit, Timer 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer run time, timer 3</source>
        <translation>Timerlaufzeit, Timer 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer run time, timer 4</source>
        <translation>Timerlaufzeit, Timer 4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary functions &quot;Program controller&quot;</source>
        <translation>Binärfunktionen &quot;Programmregler&quot;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.6 Commands</source>
        <translation>5.6 Befehle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Program canceled</source>
        <translation>Programmabbruch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Program start</source>
        <translation>Programmstart</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment change</source>
        <translation>Segmentwechsel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Store temporary change</source>
        <translation>Temporäre Änderung speichern</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary functions &quot;Controller&quot;</source>
        <translation>Binärfunktionen &quot;Regler&quot;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pause program</source>
        <translation>Programm anhalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel ramp</source>
        <translation>Rampe abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Activate manual mode</source>
        <translation>Handbetrieb aktivieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller off</source>
        <translation>Regler aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start autotuning</source>
        <translation>Selbstoptimierung starten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel autotuning</source>
        <translation>Selbstoptimierung abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary functions &quot;Operation&quot;</source>
        <translation>Binärfunktionen &quot;Bedienung&quot;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Display off with key inhibit</source>
        <translation>Anzeige aus mit Tastatursperre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acknowledge limit comparators</source>
        <translation>Grenzwertüberwachungen quittieren</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Text display</source>
        <translation>Textanzeige</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary functions &quot;Timer&quot;</source>
        <translation>Binärfunktionen &quot;Timer&quot;</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pause timer 1</source>
        <translation>Timer 1 anhalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel timer 1</source>
        <translation>Timer 1 abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start timer 1</source>
        <translation>Timer 1 starten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pause timer 2</source>
        <translation>Timer 2 anhalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel timer 2</source>
        <translation>Timer 2 abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start timer 2</source>
        <translation>Timer 2 starten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint switching</source>
        <translation>Sollwertumschaltung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>W1</source>
        <translation>W1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>W2</source>
        <translation>W2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>W3</source>
        <translation>W3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>W4</source>
        <translation>W4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set switching</source>
        <translation>Parametersatzumschaltung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P1</source>
        <translation>P1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P2</source>
        <translation>P2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 1, limit AL</source>
        <translation>Grenzwertüberwachung 1, Grenzwert AL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.4 Configuration</source>
        <translation>5.4 Konfiguration</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 1, switching differential</source>
        <translation>Grenzwertüberwachung 1, Schaltdifferenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 1, switch-on delay</source>
        <translation>Grenzwertüberwachung 1, Einschaltverzögerung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 1, switch-off delay</source>
        <translation>Grenzwertüberwachung 1, Ausschaltverzögerung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 2, limit AL</source>
        <translation>Grenzwertüberwachung 2, Grenzwert AL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 2, switching differential</source>
        <translation>Grenzwertüberwachung 2, Schaltdifferenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 2, switch-on delay</source>
        <translation>Grenzwertüberwachung 2, Einschaltverzögerung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 2, switch-off delay</source>
        <translation>Grenzwertüberwachung 2, Ausschaltverzögerung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 3, limit AL</source>
        <translation>Grenzwertüberwachung 3, Grenzwert AL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 3, switching differential</source>
        <translation>Grenzwertüberwachung 3, Schaltdifferenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 3, switch-on delay</source>
        <translation>Grenzwertüberwachung 3, Einschaltverzögerung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 3, switch-off delay</source>
        <translation>Grenzwertüberwachung 3, Ausschaltverzögerung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 4, limit AL</source>
        <translation>Grenzwertüberwachung 4, Grenzwert AL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 4, switching differential</source>
        <translation>Grenzwertüberwachung 4, Schaltdifferenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 4, switch-on delay</source>
        <translation>Grenzwertüberwachung 4, Einschaltverzögerung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit comparator 4, switch-off delay</source>
        <translation>Grenzwertüberwachung 4, Ausschaltverzögerung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramp function, slope</source>
        <translation>Rampenfunktion, Steigung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment setpoint 1</source>
        <translation>Segmentsollwert 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.5 Program transmission</source>
        <translation>5.5 Programmübertragung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment time 1</source>
        <translation>Segmentzeit 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment setpoint 2</source>
        <translation>Segmentsollwert 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment time 2</source>
        <translation>Segmentzeit 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment setpoint 3</source>
        <translation>Segmentsollwert 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment time 3</source>
        <translation>Segmentzeit 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment setpoint 4</source>
        <translation>Segmentsollwert 4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment time 4</source>
        <translation>Segmentzeit 4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment setpoint 5</source>
        <translation>Segmentsollwert 5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment time 5</source>
        <translation>Segmentzeit 5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment setpoint 6</source>
        <translation>Segmentsollwert 6</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment time 6</source>
        <translation>Segmentzeit 6</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment setpoint 7</source>
        <translation>Segmentsollwert 7</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment time 7</source>
        <translation>Segmentzeit 7</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment setpoint 8</source>
        <translation>Segmentsollwert 8</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Segment time 8</source>
        <translation>Segmentzeit 8</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contacts, segment 1</source>
        <translation>Steuerkontakte, Segment 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contacts, segment 2</source>
        <translation>Steuerkontakte, Segment 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contacts, segment 3</source>
        <translation>Steuerkontakte, Segment 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contacts, segment 4</source>
        <translation>Steuerkontakte, Segment 4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contacts, segment 5</source>
        <translation>Steuerkontakte, Segment 5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contacts, segment 6</source>
        <translation>Steuerkontakte, Segment 6</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contacts, segment 7</source>
        <translation>Steuerkontakte, Segment 7</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Control contacts, segment 8</source>
        <translation>Steuerkontakte, Segment 8</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Alarm text (1-2)</source>
        <translation>Alarmtext (1-2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Alarm text (3-4)</source>
        <translation>Alarmtext (3-4)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: Pb1</source>
        <translation>Parametersatz 1: Pb1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.3 Controller parameters</source>
        <translation>5.3 Reglerparameter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: Pb2</source>
        <translation>Parametersatz 1: Pb2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: dt</source>
        <translation>Parametersatz 1: dt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: rt</source>
        <translation>Parametersatz 1: rt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: Cy1</source>
        <translation>Parametersatz 1: Cy1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: Cy2</source>
        <translation>Parametersatz 1: Cy2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: db</source>
        <translation>Parametersatz 1: db</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: HyS1</source>
        <translation>Parametersatz 1: HyS1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: HyS2</source>
        <translation>Parametersatz 1: HyS2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: tt</source>
        <translation>Parametersatz 1: tt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: y0</source>
        <translation>Parametersatz 1: y0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: y1</source>
        <translation>Parametersatz 1: y1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 1: y2</source>
        <translation>Parametersatz 1: y2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: Pb1</source>
        <translation>Parametersatz 2: Pb1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: Pb2</source>
        <translation>Parametersatz 2: Pb2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: dt</source>
        <translation>Parametersatz 2: dt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: rt</source>
        <translation>Parametersatz 2: rt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: Cy1</source>
        <translation>Parametersatz 2: Cy1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: Cy2</source>
        <translation>Parametersatz 2: Cy2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: db</source>
        <translation>Parametersatz 2: db</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: HyS1</source>
        <translation>Parametersatz 2: HyS1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: HyS2</source>
        <translation>Parametersatz 2: HyS2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: tt</source>
        <translation>Parametersatz 2: tt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: y0</source>
        <translation>Parametersatz 2: y0</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: y1</source>
        <translation>Parametersatz 2: y1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Parameter set 2: y2</source>
        <translation>Parametersatz 2: y2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint W1</source>
        <translation>Sollwert W1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.2 Setpoints</source>
        <translation>5.2 Sollwerte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint W2</source>
        <translation>Sollwert W2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint W3</source>
        <translation>Sollwert W3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint W4</source>
        <translation>Sollwert W4</translation>
    </message>
    <message>
        <location line="-202"/>
        <source>Process value</source>
        <translation>Istwert</translation>
    </message>
    <message>
        <location line="+204"/>
        <source>Logic 1+2</source>
        <translation>Logik 1+2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Logic 1</source>
        <translation>Logik 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Logic 2</source>
        <translation>Logik 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Option slot 1+2</source>
        <translation>Optionssteckplatz 1+2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.7 Device identification</source>
        <translation>5.7 Geräteidentifikation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slot 2</source>
        <translation>Steckplatz 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slot 1</source>
        <translation>Steckplatz 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Option slot 3</source>
        <translation>Optionssteckplatz 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slot 3</source>
        <translation>Steckplatz 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device format</source>
        <translation>Geräteformat</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type 703041/45 (48 mm x 48 mm)</source>
        <translation>Typ 703041/45 (48 mm x 48 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type 703042/43/46 (48 mm x 96 mm)</source>
        <translation>Typ 703042/43/46 (48 mm x 96 mm)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type 703044/48 (96 mm x 96 mm)</source>
        <translation>Typ 703044/48 (96 mm x 96 mm)</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Invalid Modbus function</source>
        <translation>Ungültige Modbus-Funktion</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invalid data address</source>
        <translation>Ungültige Datenadresse</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data value outside admissible value range</source>
        <translation>Datenwert außerhalb des zulässigen Wertebereichs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Error when processing the instruction (e.g. unable to write to flash)</source>
        <translation>Fehler beim Ausführen des Befehls (z. B. Schreiben in den Flash nicht möglich)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Currently unable to execute the instruction, please try again</source>
        <translation>Befehl kann derzeit nicht ausgeführt werden, bitte erneut versuchen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write-protected</source>
        <translation>Schreibgeschützt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the quantity the alarm monitors, as configured on the device: V, A, W, kW, Ω, °C or °F (5.1.2: &apos;depending on what is being monitored&apos;)</source>
        <translation>die Größe, die der Alarm überwacht, wie am Gerät konfiguriert: V, A, W, kW, Ω, °C oder °F (5.1.2: „je nachdem, was überwacht wird“)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the measuring range the external current sensor is configured for: mA or A (5.2.1)</source>
        <translation>der Messbereich, für den der externe Stromsensor konfiguriert ist: mA oder A (5.2.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the standard signal the external current sensor is configured for: 0-20 mA, 4-20 mA or customer-specific (5.2.1)</source>
        <translation>das Einheitssignal, für das der externe Stromsensor konfiguriert ist: 0-20 mA, 4-20 mA oder kundenspezifisch (5.2.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measuring range underflow (underrange)</source>
        <translation>Messbereichsunterschreitung (Underrange)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Measuring range overflow (overrange)</source>
        <translation>Messbereichsüberschreitung (Overrange)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Other invalid value</source>
        <translation>Sonstiger ungültiger Wert</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Software version</source>
        <translation>Softwareversion</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.1.1 ID</source>
        <translation>5.1.1 ID</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VdN number</source>
        <translation>VdN-Nummer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Internal software version</source>
        <translation>Interne Softwareversion</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device name</source>
        <translation>Gerätename</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fabrication number</source>
        <translation>Fabrikationsnummer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inspection ID</source>
        <translation>Prüfkennung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reserve</source>
        <translation>Reserve</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Order code</source>
        <translation>Bestellschlüssel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Basic type</source>
        <translation>Grundtyp</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IPC300_709051</source>
        <translation>IPC300_709051</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nominal current</source>
        <translation>Nennstrom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>70 A</source>
        <translation>70 A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>100 A</source>
        <translation>100 A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>200 A</source>
        <translation>200 A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Equipped digital output</source>
        <translation>Bestückter Digitalausgang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Relay</source>
        <translation>Relais</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Optocoupler</source>
        <translation>Optokoppler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Equipped interface</source>
        <translation>Bestückte Schnittstelle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>None</source>
        <translation>Keine</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RS422/485</source>
        <translation>RS422/485</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PROFINET</source>
        <translation>PROFINET</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>5.1.2 Operating level parameters</source>
        <translation>5.1.2 Parameter der Bedienerebene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Switch-off of display lighting</source>
        <translation>Abschaltung der Displaybeleuchtung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load voltage limit value</source>
        <translation>Grenzwert Lastspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Current limit value</source>
        <translation>Grenzwert Strom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power limit value</source>
        <translation>Grenzwert Leistung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resistance limit value</source>
        <translation>Grenzwert Widerstand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint value in case of bus error/wire break</source>
        <translation>Sollwert bei Busfehler/Drahtbruch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Base load</source>
        <translation>Grundlast</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value for min. alarm</source>
        <translation>Grenzwert für Min.-Alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value for max. alarm</source>
        <translation>Grenzwert für Max.-Alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value for hysteresis</source>
        <translation>Hysterese der Grenzwerte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value for load monitoring</source>
        <translation>Grenzwert für Lastüberwachung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint value (fixed value) for setpoint switchover via digital input</source>
        <translation>Sollwert (Festwert) für Sollwertumschaltung über Digitaleingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load voltage</source>
        <translation>Lastspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.2.1 RMS measured values</source>
        <translation>5.2.1 Effektivwerte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load current</source>
        <translation>Laststrom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load, mains or fault current of ext. current sensor 2, scaled to standard signal</source>
        <translation>Last-, Netz- oder Fehlerstrom des ext. Stromsensors 2, skaliert auf Einheitssignal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load, mains or fault current of ext. current sensor 3, scaled to standard signal</source>
        <translation>Last-, Netz- oder Fehlerstrom des ext. Stromsensors 3, skaliert auf Einheitssignal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load, mains or fault current of ext. current sensor 2, scaled to measuring range</source>
        <translation>Last-, Netz- oder Fehlerstrom des ext. Stromsensors 2, skaliert auf Messbereich</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load, mains or fault current of ext. current sensor 3, scaled to measuring range</source>
        <translation>Last-, Netz- oder Fehlerstrom des ext. Stromsensors 3, skaliert auf Messbereich</translation>
    </message>
    <message>
        <location line="-43"/>
        <source>Power</source>
        <translation>Leistung</translation>
    </message>
    <message>
        <location line="+44"/>
        <source>Load resistance</source>
        <translation>Lastwiderstand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>DC link voltage</source>
        <translation>Zwischenkreisspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Voltage input</source>
        <translation>Spannungseingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.2.2 Analog values</source>
        <translation>5.2.2 Analogwerte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Current input</source>
        <translation>Stromeingang</translation>
    </message>
    <message>
        <location line="+246"/>
        <source>Device temperature</source>
        <translation>Gerätetemperatur</translation>
    </message>
    <message>
        <location line="-243"/>
        <source>Digital input 1</source>
        <translation>Digitaleingang 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.2.3 Digital inputs/outputs</source>
        <translation>5.2.3 Digitaleingänge/-ausgänge</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Digital input 2</source>
        <translation>Digitaleingang 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit input</source>
        <translation>Sperreingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit peak current</source>
        <translation>Sperre Spitzenstrom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>External inhibit input</source>
        <translation>Externer Sperreingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>External digital input 1</source>
        <translation>Externer Digitaleingang 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>External digital input 2</source>
        <translation>Externer Digitaleingang 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Digital output</source>
        <translation>Digitalausgang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration level &gt; Binary output &gt; Output mode = &quot;Interface signal&quot; (6.3)</source>
        <translation>Konfigurationsebene &gt; Binärausgang &gt; Ausgangsmodus = &quot;Schnittstellensignal&quot; (6.3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output level of controller</source>
        <translation>Stellgrad des Reglers</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.2.4 Controller</source>
        <translation>5.2.4 Regler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output level of PWM</source>
        <translation>Stellgrad der PWM</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Input setpoint value</source>
        <translation>Vorgabesollwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration level &gt; Setpoint value configuration &gt; Setpoint value = &quot;Via interface&quot; (6.1)</source>
        <translation>Konfigurationsebene &gt; Sollwertkonfiguration &gt; Sollwert = &quot;Über Schnittstelle&quot; (6.1)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Effective setpoint value</source>
        <translation>Wirksamer Sollwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Actual value</source>
        <translation>Istwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit active</source>
        <translation>Sperre aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.2.5 Device states</source>
        <translation>5.2.5 Gerätezustände</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Voltage limitation active</source>
        <translation>Spannungsbegrenzung aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Current limiting active</source>
        <translation>Strombegrenzung aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power limitation active</source>
        <translation>Leistungsbegrenzung aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resistance limitation active</source>
        <translation>Widerstandsbegrenzung aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limitation active</source>
        <translation>Begrenzung aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Soft start active</source>
        <translation>Sanftanlauf aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>External toggle switch of setpoint specification active</source>
        <translation>Externe Umschaltung der Sollwertvorgabe aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reconfiguration active</source>
        <translation>Neukonfiguration aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Calibration mode active</source>
        <translation>Kalibriermodus aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manual mode active</source>
        <translation>Handbetrieb aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keypad locked</source>
        <translation>Tastatur gesperrt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Display switched off</source>
        <translation>Anzeige ausgeschaltet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Voltage supply via USB only</source>
        <translation>Spannungsversorgung nur über USB</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Malfunction</source>
        <translation>Störung</translation>
    </message>
    <message>
        <location line="-86"/>
        <source>Power reduction</source>
        <translation>Leistungsreduzierung</translation>
    </message>
    <message>
        <location line="-249"/>
        <source>JUMO dTRON 304/308/316 (and plast) compact controllers</source>
        <translation>JUMO dTRON 304/308/316 (und plast) Kompaktregler</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Self-optimisation</source>
        <translation>Selbstoptimierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manual</source>
        <translation>Hand</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stopped</source>
        <translation>Gestoppt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ended</source>
        <translation>Beendet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Paused</source>
        <translation>Angehalten</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Output</source>
        <translation>Stellgrad</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Automatic</source>
        <translation>Automatik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The interface reports manual mode and self-optimisation only; a controller switched off (a command) also shows as automatic.</source>
        <translation>Die Schnittstelle meldet nur Handbetrieb und Selbstoptimierung; ein (per Befehl) ausgeschalteter Regler erscheint ebenfalls als Automatik.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Running</source>
        <translation>Läuft</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Analog input 2 (mV)</source>
        <translation>Analogeingang 2 (mV)</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Analog input 1 (degrees)</source>
        <translation>Analogeingang 1 (Grad)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Analog input 2 (degrees)</source>
        <translation>Analogeingang 2 (Grad)</translation>
    </message>
    <message>
        <location line="+137"/>
        <source>Setpoint (RAM)</source>
        <translation>Sollwert (RAM)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>JUMO IPC 300 electronic transformer</source>
        <translation>JUMO IPC 300 elektronischer Transformator</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Calibration</source>
        <translation>Kalibrierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Voltage limitation</source>
        <translation>Spannungsbegrenzung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Current limiting</source>
        <translation>Strombegrenzung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power limitation</source>
        <translation>Leistungsbegrenzung</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Voltage</source>
        <translation>Spannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Current</source>
        <translation>Strom</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Language (code)</source>
        <translation>Sprache (Code)</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Device temperature (°C)</source>
        <translation>Gerätetemperatur (°C)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device temperature (°F)</source>
        <translation>Gerätetemperatur (°F)</translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Trigger for manual Teach-In</source>
        <translation>Auslöser für manuelles Teach-In</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Malfunction signal 1</source>
        <translation>Störmeldung 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.2.6 Binary signals</source>
        <translation>5.2.6 Binärsignale</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min. alarm</source>
        <translation>Min.-Alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max. alarm</source>
        <translation>Max.-Alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load error</source>
        <translation>Lastfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load failure virtual current sensor 1</source>
        <translation>Lastausfall virtueller Stromsensor 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load failure external current sensor 2</source>
        <translation>Lastausfall externer Stromsensor 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load failure external current sensor 3</source>
        <translation>Lastausfall externer Stromsensor 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Teach-In for load monitoring is missing</source>
        <translation>Teach-In für Lastüberwachung fehlt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fuse failure</source>
        <translation>Sicherungsbruch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IGBT break</source>
        <translation>IGBT-Unterbrechung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IGBT short-circuit</source>
        <translation>IGBT-Kurzschluss</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limited power due to excess temperature</source>
        <translation>Leistungsbegrenzung wegen Übertemperatur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pre-alarm due to excess temperature</source>
        <translation>Voralarm wegen Übertemperatur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mains voltage too low</source>
        <translation>Netzspannung zu niedrig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire break at current input</source>
        <translation>Drahtbruch am Stromeingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire break at voltage input</source>
        <translation>Drahtbruch am Spannungseingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bus error</source>
        <translation>Busfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Malfunction signal 2</source>
        <translation>Störmeldung 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reserved</source>
        <translation>Reserviert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Adjustment not possible</source>
        <translation>Abgleich nicht möglich</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit due to excessive peak current</source>
        <translation>Sperre wegen zu hohem Spitzenstrom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit via UCEsat – detection 1</source>
        <translation>Sperre über UCEsat – Erkennung 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit via UCEsat – detection 2</source>
        <translation>Sperre über UCEsat – Erkennung 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Error current too large</source>
        <translation>Fehlerstrom zu groß</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Failure of fan 1</source>
        <translation>Ausfall Lüfter 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Failure of fan 2</source>
        <translation>Ausfall Lüfter 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invalid configuration</source>
        <translation>Ungültige Konfiguration</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire break at external current sensor 2</source>
        <translation>Drahtbruch am externen Stromsensor 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire break at external current sensor 3</source>
        <translation>Drahtbruch am externen Stromsensor 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>External current sensor incorrectly configured</source>
        <translation>Externer Stromsensor falsch konfiguriert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary signal 1</source>
        <translation>Binärsignal 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hardware level digital input 1</source>
        <translation>Hardwarepegel Digitaleingang 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hardware level digital input 2</source>
        <translation>Hardwarepegel Digitaleingang 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Hardware level inhibit input</source>
        <translation>Hardwarepegel Sperreingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Signal of peak current monitoring circuit</source>
        <translation>Signal der Spitzenstromüberwachung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit</source>
        <translation>Sperre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The voltage limitation is active</source>
        <translation>Die Spannungsbegrenzung ist aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The current limiting is active</source>
        <translation>Die Strombegrenzung ist aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The power limitation is active</source>
        <translation>Die Leistungsbegrenzung ist aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The resistance limitation is active</source>
        <translation>Die Widerstandsbegrenzung ist aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary signal 2</source>
        <translation>Binärsignal 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The voltage, current, power, or resistance limitation is active</source>
        <translation>Die Spannungs-, Strom-, Leistungs- oder Widerstandsbegrenzung ist aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Soft start running</source>
        <translation>Sanftanlauf läuft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The external switchover of the setpoint specification is active</source>
        <translation>Die externe Umschaltung der Sollwertvorgabe ist aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The power controller is currently being reconfigured</source>
        <translation>Der Leistungssteller wird gerade umkonfiguriert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The power controller is operating in manual mode</source>
        <translation>Der Leistungssteller arbeitet im Handbetrieb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The keypad has been locked</source>
        <translation>Die Tastatur ist gesperrt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The display lighting has been switched off</source>
        <translation>Die Displaybeleuchtung ist ausgeschaltet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reduced power due to load failure, detected by ext. current sensor(s)</source>
        <translation>Leistungsreduzierung wegen Lastausfall, erkannt durch ext. Stromsensor(en)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Trigger for manual Teach-In is active</source>
        <translation>Auslöser für manuelles Teach-In ist aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary signal (write only)</source>
        <translation>Binärsignal (nur schreiben)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.2.7 Errors and malfunctions</source>
        <translation>5.2.7 Fehler und Störungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire break at external current sensor 1</source>
        <translation>Drahtbruch am externen Stromsensor 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Energy meter configuration is incorrect</source>
        <translation>Konfiguration des Energiezählers ist fehlerhaft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SiC voltage reserve exhausted</source>
        <translation>SiC-Spannungsreserve erschöpft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit via inhibit input</source>
        <translation>Sperre über Sperreingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit via peak current</source>
        <translation>Sperre durch Spitzenstrom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit via external input</source>
        <translation>Sperre über externen Eingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit via UCE sat – detection 1</source>
        <translation>Sperre über UCE sat – Erkennung 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit via UCE sat – detection 2</source>
        <translation>Sperre über UCE sat – Erkennung 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Defect in external current sensor 2</source>
        <translation>Defekt am externen Stromsensor 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Defect in external current sensor 3</source>
        <translation>Defekt am externen Stromsensor 3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration error in external current sensor (2 and/or 3)</source>
        <translation>Konfigurationsfehler am externen Stromsensor (2 und/oder 3)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.2.8 Controlling the analog output</source>
        <translation>5.2.8 Ansteuerung des Analogausgangs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value of analog output when controlled via interface</source>
        <translation>Wert des Analogausgangs bei Ansteuerung über Schnittstelle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration level &gt; Analog output &gt; Value to be output = &quot;From interface&quot; (6.2)</source>
        <translation>Konfigurationsebene &gt; Analogausgang &gt; Auszugebender Wert = &quot;Von Schnittstelle&quot; (6.2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quantrol LC100 / LC200 / LC300 universal PID controller</source>
        <translation>Quantrol LC100 / LC200 / LC300 Universal-PID-Regler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the input type configured on the device: V, mA or Ω (4.2: &apos;Analog input [V], [mA] or [Ohm]&apos;)</source>
        <translation>die am Gerät konfigurierte Eingangsart: V, mA oder Ω (4.2: „Analogeingang [V], [mA] oder [Ohm]“)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>4.2 Process data</source>
        <translation>4.2 Prozessdaten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Self-optimization active</source>
        <translation>Selbstoptimierung aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary outputs 1 ... 5</source>
        <translation>Binärausgänge 1 ... 5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output K1: Relay</source>
        <translation>Ausgang K1: Relais</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output K2: Relay or Logic</source>
        <translation>Ausgang K2: Relais oder Logik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output K3: Relay or Logic</source>
        <translation>Ausgang K3: Relais oder Logik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output K4: Relay or Logic</source>
        <translation>Ausgang K4: Relais oder Logik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output K5: Relay or Logic</source>
        <translation>Ausgang K5: Relais oder Logik</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary input</source>
        <translation>Binäreingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Input 1</source>
        <translation>Eingang 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value monitoring</source>
        <translation>Grenzwertüberwachung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value monitoring 1</source>
        <translation>Grenzwertüberwachung 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value monitoring 2</source>
        <translation>Grenzwertüberwachung 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output K1</source>
        <translation>Ausgang K1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output K2</source>
        <translation>Ausgang K2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output K3</source>
        <translation>Ausgang K3</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output K4</source>
        <translation>Ausgang K4</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output K5</source>
        <translation>Ausgang K5</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Analog input</source>
        <translation>Analogeingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Internal cold junction</source>
        <translation>Interne Vergleichsstelle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Analog input (displayed value)</source>
        <translation>Analogeingang (Anzeigewert)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sampling time</source>
        <translation>Abtastzeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller, ramp end value</source>
        <translation>Regler, Rampenendwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller, actual value, filtered</source>
        <translation>Regler, Istwert, gefiltert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller, actual value, unfiltered</source>
        <translation>Regler, Istwert, ungefiltert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller, setpoint</source>
        <translation>Regler, Sollwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller, output level display</source>
        <translation>Regler, Stellgradanzeige</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output level, controller output 1 (heating)</source>
        <translation>Stellgrad, Reglerausgang 1 (Heizen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output level, controller output 2 (cooling)</source>
        <translation>Stellgrad, Reglerausgang 2 (Kühlen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller, control difference</source>
        <translation>Regler, Regelabweichung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Switching state, controller output 1 (heating)</source>
        <translation>Schaltzustand, Reglerausgang 1 (Heizen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Switching state, controller output 2 (cooling)</source>
        <translation>Schaltzustand, Reglerausgang 2 (Kühlen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output level, manual mode</source>
        <translation>Stellgrad, Handbetrieb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer run time</source>
        <translation>Timer-Laufzeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Residual timer time</source>
        <translation>Timer-Restzeit</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer status</source>
        <translation>Timer-Status</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer stopped</source>
        <translation>Timer angehalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer runs</source>
        <translation>Timer läuft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer end</source>
        <translation>Timer-Ende</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer signal</source>
        <translation>Timer-Signal</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary functions CONTROLLER</source>
        <translation>Binärfunktionen REGLER</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>4.6 Commands</source>
        <translation>4.6 Befehle</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Self-optimization start</source>
        <translation>Start Selbstoptimierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Self-optimization abort</source>
        <translation>Abbruch Selbstoptimierung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Manual mode inhibit</source>
        <translation>Sperre Handbetrieb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramp stop</source>
        <translation>Rampe anhalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramp abort</source>
        <translation>Rampe abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramp restart</source>
        <translation>Rampe neu starten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer start</source>
        <translation>Timer starten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer abort</source>
        <translation>Timer abbrechen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer stop</source>
        <translation>Timer anhalten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary functions OPERATION</source>
        <translation>Binärfunktionen BEDIENUNG</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keyboard inhibit</source>
        <translation>Tastatursperre</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration and parameter level inhibit</source>
        <translation>Sperre Konfigurations- und Parameterebene</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Display OFF</source>
        <translation>Anzeige AUS</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint changeover</source>
        <translation>Sollwertumschaltung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint 1</source>
        <translation>Sollwert 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint 2</source>
        <translation>Sollwert 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ramp function, ramp rate</source>
        <translation>Rampenfunktion, Rampensteigung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>4.5 Configuration</source>
        <translation>4.5 Konfiguration</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Filter time constant</source>
        <translation>Filterzeitkonstante</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Offset analog input</source>
        <translation>Offset Analogeingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timer value</source>
        <translation>Timerwert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value monitoring 1, alarm value AL</source>
        <translation>Grenzwertüberwachung 1, Grenzwert AL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value monitoring 1, hysteresis</source>
        <translation>Grenzwertüberwachung 1, Schaltdifferenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value monitoring 2, alarm value AL</source>
        <translation>Grenzwertüberwachung 2, Grenzwert AL</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value monitoring 2, hysteresis</source>
        <translation>Grenzwertüberwachung 2, Schaltdifferenz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter XP1 (Pb)</source>
        <translation>Reglerparameter XP1 (Pb)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>4.4 Controller parameters</source>
        <translation>4.4 Reglerparameter</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter XP2 (Pb2)</source>
        <translation>Reglerparameter XP2 (Pb2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter TV (dt)</source>
        <translation>Reglerparameter TV (dt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter TN (rt)</source>
        <translation>Reglerparameter TN (rt)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter CY1 (CY)</source>
        <translation>Reglerparameter CY1 (CY)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter CY2 (CY2)</source>
        <translation>Reglerparameter CY2 (CY2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter XSH (db)</source>
        <translation>Reglerparameter XSH (db)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter XD1 (HYS)</source>
        <translation>Reglerparameter XD1 (HYS)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter XD2 (HYS2)</source>
        <translation>Reglerparameter XD2 (HYS2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter Y0 (Y0)</source>
        <translation>Reglerparameter Y0 (Y0)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter Y1 (Y)</source>
        <translation>Reglerparameter Y1 (Y)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller parameter Y2 (Y2)</source>
        <translation>Reglerparameter Y2 (Y2)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint SP1</source>
        <translation>Sollwert SP1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>4.3 Setpoints</source>
        <translation>4.3 Sollwerte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint SP2</source>
        <translation>Sollwert SP2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller setpoint (writable)</source>
        <translation>Reglersollwert (beschreibbar)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>4.7 RAM memory</source>
        <translation>4.7 RAM-Speicher</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Controller actual value (writable)</source>
        <translation>Regleristwert (beschreibbar)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>JUMO TYA 200 thyristor power units</source>
        <translation>JUMO TYA 200 Thyristor-Leistungssteller</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Invalid data address (also sent when more words than admissible are to be read or written)</source>
        <translation>Ungültige Datenadresse (wird auch gesendet, wenn mehr Worte als zulässig gelesen oder geschrieben werden sollen)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data value outside the admissible value range</source>
        <translation>Datenwert außerhalb des zulässigen Wertebereichs</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Error while processing the instruction (e.g. could not write to flash memory)</source>
        <translation>Fehler bei der Ausführung des Befehls (z. B. Flash-Speicher konnte nicht beschrieben werden)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Instruction cannot be carried out at this time, try again</source>
        <translation>Befehl kann zurzeit nicht ausgeführt werden, bitte erneut versuchen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the quantity the alarm monitors, as configured on the device: V, A, W, kW, Ω, °C or °F (5.8: &apos;depending on the monitored value&apos;)</source>
        <translation>die Größe, die der Alarm überwacht, wie am Gerät konfiguriert: V, A, W, kW, Ω, °C oder °F (5.8: „abhängig vom überwachten Wert“)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>External current limit</source>
        <translation>Externe Strombegrenzung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.1 Device data</source>
        <translation>5.1 Gerätedaten</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial number</source>
        <translation>Seriennummer</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type key</source>
        <translation>Typenschlüssel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.2 Type codes and options</source>
        <translation>5.2 Typangaben und Optionen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>709061 (TYA 201 - single-phase unit)</source>
        <translation>709061 (TYA 201 - Einzelgerät)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>709062 (TYA 202 - economy circuit)</source>
        <translation>709062 (TYA 202 - Sparschaltung)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>709063 (TYA 203 - three-phase power controller)</source>
        <translation>709063 (TYA 203 - Dreiphasen-Leistungssteller)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Nominal voltage</source>
        <translation>Nennspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>24 V</source>
        <translation>24 V</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>42 V</source>
        <translation>42 V</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>115 V</source>
        <translation>115 V</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>230 V</source>
        <translation>230 V</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>265 V</source>
        <translation>265 V</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>400 V</source>
        <translation>400 V</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>440 V</source>
        <translation>440 V</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>500 V</source>
        <translation>500 V</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rated current</source>
        <translation>Nennstrom</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>16 A</source>
        <translation>16 A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>30 A</source>
        <translation>30 A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>50 A</source>
        <translation>50 A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>75 A</source>
        <translation>75 A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>150 A</source>
        <translation>150 A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>250 A</source>
        <translation>250 A</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Current measurement option</source>
        <translation>Option Strommessung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No</source>
        <translation>Nein</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yes</source>
        <translation>Ja</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Released options</source>
        <translation>Freigeschaltete Optionen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P control option</source>
        <translation>Option P-Regelung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device can only be used as slave</source>
        <translation>Gerät nur als Slave verwendbar</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Equipped binary output</source>
        <translation>Bestückter Binärausgang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>RS422/RS485</source>
        <translation>RS422/RS485</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Profibus</source>
        <translation>Profibus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Switch off display light in</source>
        <translation>Displaybeleuchtung ausschalten nach</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.8 Parameters of the operator level (storage in the RAM)</source>
        <translation>5.8 Parameter der Bedienerebene (Speicherung im RAM)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle alpha start</source>
        <translation>Startwinkel Alpha</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Maximum actuating variable</source>
        <translation>Maximaler Stellgrad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min. limit value alarm</source>
        <translation>Grenzwert Min-Alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max. limit value alarm</source>
        <translation>Grenzwert Max-Alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value hysteresis</source>
        <translation>Grenzwert-Hysterese</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limit value load monitoring</source>
        <translation>Grenzwert Lastkreisüberwachung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint in the case of a bus error/wire break</source>
        <translation>Sollwert bei Busfehler/Drahtbruch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.3 Measured values</source>
        <translation>5.3 Messwerte</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Config level → Set point value config. → Default set point value = &quot;via interface&quot; (6.1); otherwise writes are ignored.</source>
        <translation>Konfigurationsebene → Sollwertkonfiguration → Sollwertvorgabe = &quot;über Schnittstelle&quot; (6.1); andernfalls werden Schreibzugriffe ignoriert.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output level</source>
        <translation>Stellgrad</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Alpha</source>
        <translation>Alpha</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mains voltage</source>
        <translation>Netzspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mains frequency</source>
        <translation>Netzfrequenz</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Load voltage slave/slave1</source>
        <translation>Lastspannung Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load current slave/slave1</source>
        <translation>Laststrom Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power slave/slave1</source>
        <translation>Leistung Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load resistance slave/slave1</source>
        <translation>Lastwiderstand Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mains voltage slave/slave1</source>
        <translation>Netzspannung Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device temp. slave/slave1</source>
        <translation>Gerätetemp. Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load voltage slave2</source>
        <translation>Lastspannung Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load current slave2</source>
        <translation>Laststrom Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power slave2</source>
        <translation>Leistung Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load resistance slave2</source>
        <translation>Lastwiderstand Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mains voltage slave2</source>
        <translation>Netzspannung Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device temp. slave2</source>
        <translation>Gerätetemp. Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Three-phase power</source>
        <translation>Drehstromleistung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Alpha default value</source>
        <translation>Alpha-Vorgabewert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Logic mode (Config level → Power controller → SCR control = &quot;Logics (switch)&quot;) with the default α value set to &quot;via interface&quot; under Config level → Set point value config. (6.2; the menu path is cut off in the manual).</source>
        <translation>Logikbetrieb (Konfigurationsebene → Leistungssteller → Thyristoransteuerung = &quot;Logik (Schalter)&quot;) mit α-Vorgabewert auf &quot;über Schnittstelle&quot; unter Konfigurationsebene → Sollwertkonfiguration (6.2; der Menüpfad ist im Handbuch abgeschnitten).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Analog output</source>
        <translation>Analogausgang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Config level → Analog output → Output value = &quot;From Interface&quot; (6.3; table: only writable if &quot;via interface&quot; is configured); signal range start 0 %, end 100 % recommended.</source>
        <translation>Konfigurationsebene → Analogausgang → Ausgabewert = &quot;Von Schnittstelle&quot; (6.3; Tabelle: nur beschreibbar, wenn &quot;über Schnittstelle&quot; konfiguriert ist); Signalbereich Anfang 0 %, Ende 100 % empfohlen.</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary signals - 1st section</source>
        <translation>Binärsignale - 1. Abschnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.4 Binary signals (bit field)</source>
        <translation>5.4 Binärsignale (Bitfeld)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>External binary input 1</source>
        <translation>Externer Binäreingang 1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>External binary input 2</source>
        <translation>Externer Binäreingang 2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary output</source>
        <translation>Binärausgang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit by the slave</source>
        <translation>Sperre durch den Slave</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Soft start is still running</source>
        <translation>Sanftanlauf läuft noch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Current limiting is active</source>
        <translation>Strombegrenzung ist aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>External change-over to phase angle is active</source>
        <translation>Externe Umschaltung auf Phasenanschnitt ist aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>External current limit value is used</source>
        <translation>Externer Stromgrenzwert wird verwendet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Display PCB is connected</source>
        <translation>Displayplatine ist angeschlossen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power controller is currently reconfigured</source>
        <translation>Leistungssteller wird gerade umkonfiguriert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power controller operates in the test and calibration mode</source>
        <translation>Leistungssteller arbeitet im Test- und Kalibriermodus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Binary signals - 2nd section</source>
        <translation>Binärsignale - 2. Abschnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power controller operates in manual mode</source>
        <translation>Leistungssteller arbeitet im Handbetrieb</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keyboard is locked</source>
        <translation>Tastatur ist gesperrt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Display is switched off</source>
        <translation>Anzeige ist ausgeschaltet</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power controller is connected to the supply voltage</source>
        <translation>Leistungssteller ist an die Versorgungsspannung angeschlossen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slave/slave1 power controller is connected to the supply voltage</source>
        <translation>Leistungssteller Slave/Slave1 ist an die Versorgungsspannung angeschlossen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rotary field detection was successfully completed</source>
        <translation>Drehfelderkennung wurde erfolgreich abgeschlossen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resistance limitation is active</source>
        <translation>Widerstandsbegrenzung ist aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>External switching of setpoint value is active</source>
        <translation>Externe Sollwertumschaltung ist aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slave2 is connected to the supply voltage</source>
        <translation>Slave2 ist an die Versorgungsspannung angeschlossen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit of slave2</source>
        <translation>Sperre von Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Malfunction signals - 1st section</source>
        <translation>Störmeldungen - 1. Abschnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min alarm</source>
        <translation>Min-Alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max alarm</source>
        <translation>Max-Alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Teach-in for load monitoring is still missing</source>
        <translation>Teach-In für Lastkreisüberwachung fehlt noch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Blown fuse</source>
        <translation>Sicherungsbruch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thyristor breakage</source>
        <translation>Thyristorbruch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thyristor short circuit</source>
        <translation>Thyristorkurzschluss</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Performance limitation due to over-temperature</source>
        <translation>Leistungsbegrenzung wegen Übertemperatur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Over-temperature</source>
        <translation>Übertemperatur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Supply voltage too low</source>
        <translation>Versorgungsspannung zu niedrig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Supply voltage too high</source>
        <translation>Versorgungsspannung zu hoch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temporary supply voltage drop</source>
        <translation>Kurzzeitiger Einbruch der Versorgungsspannung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire breakage on input current</source>
        <translation>Drahtbruch am Stromeingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire breakage on input voltage</source>
        <translation>Drahtbruch am Spannungseingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Malfunction signals - 2nd section</source>
        <translation>Störmeldungen - 2. Abschnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min alarm on slave/slave1</source>
        <translation>Min-Alarm an Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max alarm on slave/slave1</source>
        <translation>Max-Alarm an Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load error on slave/slave1</source>
        <translation>Lastfehler an Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Blown fuse at the slave or slave1</source>
        <translation>Sicherungsbruch an Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thyristor breakage at the slave/slave1</source>
        <translation>Thyristorbruch an Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thyristor short circuit at the slave/slave1</source>
        <translation>Thyristorkurzschluss an Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Performance limitation due to over-temperature in slave/slave1</source>
        <translation>Leistungsbegrenzung wegen Übertemperatur in Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Over-temperature in slave/slave1</source>
        <translation>Übertemperatur in Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Supply voltage slave/slave1 too low</source>
        <translation>Versorgungsspannung Slave/Slave1 zu niedrig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Supply voltage slave/slave1 too high</source>
        <translation>Versorgungsspannung Slave/Slave1 zu hoch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temporary supply voltage drop at slave/slave1</source>
        <translation>Kurzzeitiger Einbruch der Versorgungsspannung an Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wrong energy counter configuration</source>
        <translation>Falsche Konfiguration des Energiezählers</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Malfunction signals - 3rd section</source>
        <translation>Störmeldungen - 3. Abschnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Master/slave synchronization has failed</source>
        <translation>Master/Slave-Synchronisation fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Error in the master/slave communication</source>
        <translation>Fehler in der Master/Slave-Kommunikation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Error on the data cable between master and slave</source>
        <translation>Fehler an der Datenleitung zwischen Master und Slave</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rotary field detection has failed</source>
        <translation>Drehfelderkennung fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rotary field error</source>
        <translation>Drehfeldfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wiring error</source>
        <translation>Verdrahtungsfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power controller or one of the slaves is incompatible</source>
        <translation>Leistungssteller oder einer der Slaves ist inkompatibel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Regulation not possible</source>
        <translation>Regelung nicht möglich</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Malfunction signals - 4th section</source>
        <translation>Störmeldungen - 4. Abschnitt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Min alarm on slave2</source>
        <translation>Min-Alarm an Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max alarm on slave2</source>
        <translation>Max-Alarm an Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load error on slave2</source>
        <translation>Lastfehler an Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Blown fuse at the slave2</source>
        <translation>Sicherungsbruch an Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thyristor breakage at the slave2</source>
        <translation>Thyristorbruch an Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thyristor short circuit at the slave2</source>
        <translation>Thyristorkurzschluss an Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Performance limitation due to over-temperature in slave2</source>
        <translation>Leistungsbegrenzung wegen Übertemperatur in Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Over-temperature in slave2</source>
        <translation>Übertemperatur in Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Supply voltage slave2 too low</source>
        <translation>Versorgungsspannung Slave2 zu niedrig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Supply voltage slave2 too high</source>
        <translation>Versorgungsspannung Slave2 zu hoch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temporary supply voltage drop at slave2</source>
        <translation>Kurzzeitiger Einbruch der Versorgungsspannung an Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Systembus: invalid configuration</source>
        <translation>Systembus: ungültige Konfiguration</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Systembus: watchdog timeout</source>
        <translation>Systembus: Watchdog-Zeitüberschreitung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Systembus: local error</source>
        <translation>Systembus: lokaler Fehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.5 Digital inputs and -output</source>
        <translation>5.5 Digitaleingänge und -ausgang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Config level → Binary output → Output mode binary out = &quot;Interf.sign.outp&quot; (6.4; table: only writable if &quot;interface-signal&quot; is configured).</source>
        <translation>Konfigurationsebene → Binärausgang → Ausgabemodus Binärausgang = &quot;Schnittst.-Signal&quot; (6.4; Tabelle: nur beschreibbar, wenn &quot;Schnittstellensignal&quot; konfiguriert ist).</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.6 Device status</source>
        <translation>5.6 Gerätestatus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit slave/slave1</source>
        <translation>Sperre Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Soft start phase</source>
        <translation>Sanftanlaufphase</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Current limitation active</source>
        <translation>Strombegrenzung aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ext. change-over to phase angle active</source>
        <translation>Ext. Umschaltung auf Phasenanschnitt aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ext. current limit value active</source>
        <translation>Ext. Stromgrenzwert aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The display socket is connected</source>
        <translation>Displayanschluss ist belegt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power controller is in calibrating mode</source>
        <translation>Leistungssteller ist im Kalibriermodus</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Keyboard locked</source>
        <translation>Tastatur gesperrt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Display lighting deactivated</source>
        <translation>Displaybeleuchtung deaktiviert</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Power controller is connected on power supply</source>
        <translation>Leistungssteller ist an Versorgungsspannung angeschlossen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slave/slave1 is connected on power supply</source>
        <translation>Slave/Slave1 ist an Versorgungsspannung angeschlossen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rotating field detected</source>
        <translation>Drehfeld erkannt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ext. change-over of setpoint specification active</source>
        <translation>Ext. Umschaltung der Sollwertvorgabe aktiv</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Slave2 is connected on power supply</source>
        <translation>Slave2 ist an Versorgungsspannung angeschlossen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inhibit slave2</source>
        <translation>Sperre Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Collective fault</source>
        <translation>Sammelstörung</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>5.7 Faults</source>
        <translation>5.7 Störungen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Low alarm</source>
        <translation>Min-Alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>High alarm</source>
        <translation>Max-Alarm</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Missing teach-in</source>
        <translation>Teach-In fehlt</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thyristor short-circuit</source>
        <translation>Thyristorkurzschluss</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limitation active due to overtemperature</source>
        <translation>Begrenzung aktiv wegen Übertemperatur</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mains voltage is too low</source>
        <translation>Netzspannung ist zu niedrig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mains voltage is too high</source>
        <translation>Netzspannung ist zu hoch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Short-term mains drop</source>
        <translation>Kurzzeitiger Netzeinbruch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire break current input</source>
        <translation>Drahtbruch Stromeingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Wire break voltage input</source>
        <translation>Drahtbruch Spannungseingang</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>System bus error</source>
        <translation>Systembusfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Low alarm slave/slave1</source>
        <translation>Min-Alarm Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>High alarm slave/slave1</source>
        <translation>Max-Alarm Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load error slave/slave1</source>
        <translation>Lastfehler Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fuse breakage slave/slave1</source>
        <translation>Sicherungsbruch Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thyristor breakage slave/slave1</source>
        <translation>Thyristorbruch Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thyristor short-circuit slave/slave1</source>
        <translation>Thyristorkurzschluss Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limitation active due to overtemperature of slave/slave1</source>
        <translation>Begrenzung aktiv wegen Übertemperatur von Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Over-temperature slave/slave1</source>
        <translation>Übertemperatur Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mains voltage of slave/slave1 is too low</source>
        <translation>Netzspannung von Slave/Slave1 ist zu niedrig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mains voltage of slave/slave1 is too high</source>
        <translation>Netzspannung von Slave/Slave1 ist zu hoch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Short-term mains drop slave/slave1</source>
        <translation>Kurzzeitiger Netzeinbruch Slave/Slave1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Master slave synchronisation failed</source>
        <translation>Master-Slave-Synchronisation fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Error in master slave communication</source>
        <translation>Fehler in der Master-Slave-Kommunikation</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data cable faulty</source>
        <translation>Datenleitung fehlerhaft</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rotation field detection failed</source>
        <translation>Drehfelderkennung fehlgeschlagen</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rotation field error</source>
        <translation>Drehfeldfehler</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The or one of the slave controllers is incompatible</source>
        <translation>Der bzw. einer der Slave-Steller ist inkompatibel</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Setpoint cannot be reached</source>
        <translation>Sollwert kann nicht erreicht werden</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Low alarm slave2</source>
        <translation>Min-Alarm Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Max alarm slave2</source>
        <translation>Max-Alarm Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load error slave2</source>
        <translation>Lastfehler Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fuse breakage slave2</source>
        <translation>Sicherungsbruch Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thyristor breakage slave2</source>
        <translation>Thyristorbruch Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Thyristor short-circuit slave2</source>
        <translation>Thyristorkurzschluss Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Limitation active due to overtemperature of slave2</source>
        <translation>Begrenzung aktiv wegen Übertemperatur von Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Over-temperature slave2</source>
        <translation>Übertemperatur Slave2</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mains voltage of slave2 is too low</source>
        <translation>Netzspannung von Slave2 ist zu niedrig</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mains voltage of slave2 is too high</source>
        <translation>Netzspannung von Slave2 ist zu hoch</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Short-term mains drop slave2</source>
        <translation>Kurzzeitiger Netzeinbruch Slave2</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/jumo-hmi.cpp" line="+135"/>
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
        <location line="+6"/>
        <source>With --show: open this tab of the device page (0 = live values).</source>
        <translation>Mit --show: diese Registerkarte der Geräteseite öffnen (0 = Live-Werte).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Connect to this line at start: a serial port, tcp://HOST[:PORT] (a Modbus TCP gateway) or rtu+tcp://HOST:PORT (a serial device server); with --baud, --format, --device.</source>
        <translation>Beim Start mit dieser Leitung verbinden: eine serielle Schnittstelle, tcp://HOST[:PORT] (ein Modbus-TCP-Gateway) oder rtu+tcp://HOST:PORT (ein serieller Geräteserver); mit --baud, --format, --device.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Baud rate for --port (default 9600).</source>
        <translation>Baudrate für --port (Standard 9600).</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Data format for --port (default 8N1).</source>
        <translation>Datenformat für --port (Standard 8N1).</translation>
    </message>
    <message>
        <location line="-13"/>
        <source>Open the page of this device, e.g. ipc300@1 (line2/ipc300@1 with several lines).</source>
        <translation>Die Seite dieses Geräts öffnen, z. B. ipc300@1 (line2/ipc300@1 bei mehreren Leitungen).</translation>
    </message>
    <message>
        <location line="-97"/>
        <source>--%1 does not go with --remote: a remote view reads the broker only</source>
        <translation>--%1 passt nicht zu --remote: eine Fernansicht liest nur den Broker</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>&apos;%1&apos; cannot be a topic prefix</source>
        <translation>&apos;%1&apos; kann kein Topic-Präfix sein</translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Settings cannot be saved (%1 is not writable): what is changed in this run is lost when it ends</source>
        <translation>Die Einstellungen können nicht gespeichert werden (%1 ist nicht beschreibbar): was in diesem Lauf geändert wird, geht an seinem Ende verloren</translation>
    </message>
    <message>
        <location line="+39"/>
        <source>A line of this run, repeatable: ADDRESS[,name=NAME][,baud=N][,format=8N1][,timeout=MS][,min-response=MS][,retries=N][,read-only]; ADDRESS is a serial port, tcp://HOST:PORT or rtu+tcp://HOST:PORT. The lines kept in the settings are left as they are.</source>
        <translation>Eine Leitung dieses Laufs, wiederholbar: ADRESSE[,name=NAME][,baud=N][,format=8N1][,timeout=MS][,min-response=MS][,retries=N][,read-only]; ADRESSE ist eine serielle Schnittstelle, tcp://HOST:PORT oder rtu+tcp://HOST:PORT. Die in den Einstellungen gespeicherten Leitungen bleiben, wie sie sind.</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>The lines and devices of this run from a station file (JSON, see README); the kept lines are left as they are.</source>
        <translation>Die Leitungen und Geräte dieses Laufs aus einer Stationsdatei (JSON, siehe README); die gespeicherten Leitungen bleiben, wie sie sind.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A device to monitor, e.g. ipc300@1, or line2/ipc300@1 with several lines (repeatable).</source>
        <translation>Ein zu beobachtendes Gerät, z. B. ipc300@1, oder line2/ipc300@1 bei mehreren Leitungen (wiederholbar).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Trust the named families without checking the devices&apos; identity registers (for devices that cannot report them); the write audit log records it.</source>
        <translation>Den angegebenen Familien vertrauen, ohne die Identitätsregister der Geräte zu prüfen (für Geräte, die sie nicht melden können); das Schreibprotokoll vermerkt es.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Colours for this run: system, light, dark or high-contrast (default: the theme chosen in the View menu, else system).</source>
        <translation>Farben für diesen Lauf: system, light, dark oder high-contrast (Vorgabe: das im Menü Ansicht gewählte Farbschema, sonst system).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Control-room viewer: show the stations that publish to this MQTT broker (mqtt://[USER@]HOST[:PORT] or mqtts://...), with no Modbus access and nothing that can write.</source>
        <translation>Leitwarten-Ansicht: zeigt die Stationen, die an diesen MQTT-Broker senden (mqtt://[BENUTZER@]HOST[:PORT] oder mqtts://...), ohne Modbus-Zugriff und ohne etwas, das schreiben kann.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>With --remote: only this station (default: every station).</source>
        <translation>Mit --remote: nur diese Station (Vorgabe: jede Station).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>With --remote: the topic prefix (default jumo).</source>
        <translation>Mit --remote: das Topic-Präfix (Vorgabe jumo).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>With --remote: a file whose first line is the broker password (else JUMO_MQTT_PASSWORD; never on the command line).</source>
        <translation>Mit --remote: eine Datei, deren erste Zeile das Broker-Passwort ist (sonst JUMO_MQTT_PASSWORD; nie auf der Befehlszeile).</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>With --remote: the CA certificate that signed the broker&apos;s.</source>
        <translation>Mit --remote: das CA-Zertifikat, das das des Brokers signiert hat.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>With --remote: a client certificate (with --tls-key).</source>
        <translation>Mit --remote: ein Client-Zertifikat (mit --tls-key).</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>With --remote: the client certificate&apos;s key.</source>
        <translation>Mit --remote: der Schlüssel des Client-Zertifikats.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Print on stderr when the first live value arrives.</source>
        <translation>Auf stderr ausgeben, wann der erste Live-Wert eintrifft.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>For benchmarks: print on stderr every second how many faceplates are on screen and how old the values they show are.</source>
        <translation>Für Benchmarks: jede Sekunde auf stderr ausgeben, wie viele Faceplates zu sehen sind und wie alt die gezeigten Werte sind.</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Show Qt&apos;s Modbus messages (CRC errors, timeouts, frames) on stderr.</source>
        <translation>Die Modbus-Meldungen von Qt (CRC-Fehler, Zeitüberschreitungen, Telegramme) auf stderr ausgeben.</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>jumo-hmi: no display to open the window on (DISPLAY or WAYLAND_DISPLAY is not set or cannot be reached): start it in a desktop session</source>
        <translation>jumo-hmi: keine Anzeige, auf der das Fenster geöffnet werden kann (DISPLAY oder WAYLAND_DISPLAY ist nicht gesetzt oder nicht erreichbar): starten Sie es in einer Desktop-Sitzung</translation>
    </message>
    <message>
        <location line="+27"/>
        <source>jumo-hmi: unknown theme &apos;%1&apos; (system, light, dark or high-contrast)</source>
        <translation>jumo-hmi: unbekanntes Farbschema „%1“ (system, light, dark oder high-contrast)</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>jumo-hmi: --%1 goes with --remote only</source>
        <translation>jumo-hmi: --%1 gehört nur zu --remote</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>read-only mode is set by the system configuration (%1): nothing is written to the devices</source>
        <translation>Der Nur-Lese-Modus ist durch die Systemkonfiguration festgelegt (%1): Es wird nichts auf die Geräte geschrieben</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>give the lines one way: --port, --line (repeatable), --station or --demo</source>
        <translation>die Leitungen auf eine Weise angeben: --port, --line (wiederholbar), --station oder --demo</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>--baud %1 --format %2: no line format of this program (e.g. --baud 19200 --format 8E1)</source>
        <translation>--baud %1 --format %2: kein Leitungsformat dieses Programms (z. B. --baud 19200 --format 8E1)</translation>
    </message>
    <message>
        <location line="+24"/>
        <source>--device needs the line it is on: --port, --line or --station</source>
        <translation>--device braucht die Leitung, an der es ist: --port, --line oder --station</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the station has no lines</source>
        <translation>die Station hat keine Leitungen</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>Map files refused: %1</source>
        <translation>Map-Dateien abgelehnt: %1</translation>
    </message>
    <message>
        <location filename="../app/jumo-sim.cpp" line="+58"/>
        <source>Simulated JUMO devices on a serial line, or behind TCP as a Modbus TCP gateway or a serial device server. DEVICE is FAMILY@ADDRESS, e.g. ipc300@1.</source>
        <translation>Simulierte JUMO-Geräte an einer seriellen Leitung oder hinter TCP als Modbus-TCP-Gateway oder serieller Geräteserver. DEVICE ist FAMILY@ADDRESS, z. B. ipc300@1.</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Serial port to serve.</source>
        <translation>Zu bedienende serielle Schnittstelle.</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Make a pseudo-terminal pair in this folder (needs socat); clients connect to FOLDER/master.</source>
        <translation>Ein Pseudo-Terminal-Paar in diesem Ordner anlegen (benötigt socat); Clients verbinden sich mit FOLDER/master.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Be a Modbus TCP gateway listening on [HOST:]PORT (port 0: any free one); clients connect to tcp://HOST:PORT.</source>
        <translation>Als Modbus-TCP-Gateway auf [HOST:]PORT lauschen (Port 0: ein beliebiger freier); Clients verbinden sich mit tcp://HOST:PORT.</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Be a serial device server (raw RTU frames over TCP) listening on [HOST:]PORT; clients connect to rtu+tcp://HOST:PORT.</source>
        <translation>Als serieller Geräteserver (reine RTU-Telegramme über TCP) auf [HOST:]PORT lauschen; Clients verbinden sich mit rtu+tcp://HOST:PORT.</translation>
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
        <location line="+6"/>
        <source>give exactly one of --port, --pty, --tcp and --rtu-tcp</source>
        <translation>geben Sie genau eine der Optionen --port, --pty, --tcp und --rtu-tcp an</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>refused map file: %1</source>
        <translation>Map-Datei abgelehnt: %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--delay must be 0..10000 ms and --min-response 0..500 ms</source>
        <translation>--delay muss 0..10000 ms und --min-response 0..500 ms sein</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>name at least one device, e.g. ipc300@1</source>
        <translation>mindestens ein Gerät angeben, z. B. ipc300@1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&apos;%1&apos; is not FAMILY@ADDRESS with a known family</source>
        <translation>&apos;%1&apos; ist nicht FAMILY@ADDRESS mit einer bekannten Gerätefamilie</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>&apos;%1&apos;: %2 devices cannot be set to %3 baud %4 (they support %5 baud, %6)</source>
        <translation>&apos;%1&apos;: %2-Geräte können nicht auf %3 Baud %4 eingestellt werden (sie unterstützen %5 Baud, %6)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>cannot open %1: %2</source>
        <translation>%1 kann nicht geöffnet werden: %2</translation>
    </message>
    <message numerus="yes">
        <location line="+4"/>
        <location line="+29"/>
        <source>serving %n device(s) on %1</source>
        <translation>
            <numerusform>bedient %n Gerät an %1</numerusform>
            <numerusform>bedient %n Geräte an %1</numerusform>
        </translation>
    </message>
    <message>
        <location line="-17"/>
        <source>&apos;%1&apos; is not [HOST:]PORT</source>
        <translation>&apos;%1&apos; ist nicht [HOST:]PORT</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>cannot listen on %1: %2</source>
        <translation>kann nicht auf %1 lauschen: %2</translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+10"/>
        <source>connect to %1</source>
        <translation>verbinden mit %1</translation>
    </message>
    <message>
        <location line="-4"/>
        <source>warning: the devices answer at any settings: cannot watch %1: %2</source>
        <translation>Warnung: die Geräte antworten bei jeder Einstellung: %1 kann nicht beobachtet werden: %2</translation>
    </message>
</context>
</TS>
