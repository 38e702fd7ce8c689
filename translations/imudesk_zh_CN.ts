<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>BandwidthCalculator</name>
    <message>
        <location filename="../core/settings/bandwidth_calculator.cpp" line="+70"/>
        <source>The output needs %1 bytes/s but %2 baud carries only %3 bytes/s (%4 %): frames will be lost. %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Raise the baud rate to %1 or lower the rates.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Lower the rates or turn some messages off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The output uses %1 % of the link at %2 baud: little margin left, a higher baud rate is safer.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CanDecoder</name>
    <message>
        <location filename="../core/protocol/can/can_decoder.cpp" line="+70"/>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>HEC495 %1 axis: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+77"/>
        <source>HEC495 write 0x%1 confirmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-76"/>
        <location line="+77"/>
        <source>HEC495 write %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-65"/>
        <source>PGN %1 %2: %3-%4-%5 %6:%7:%8.%9</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>heading %1 deg (CW); %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>PGN %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>config %1 -&gt; %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>NMT command 0x%1 to node %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>SYNC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>heartbeat node %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>node %1: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>to node %1: </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>HEC495 PDO %1 (%2): %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>fixed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>float</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>TPDO%1 %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>TPDO with a wrong length (%1 bytes)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CaptureExporter</name>
    <message>
        <location filename="../core/record/capture_exporter.cpp" line="+68"/>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+99"/>
        <location line="+24"/>
        <source>Writing %1 failed: %2. Check the free disk space.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+111"/>
        <source>No output file was given.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The time range is empty (from %1 s to %2 s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+35"/>
        <source>Export cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+10"/>
        <source>%n damaged chunk(s) were skipped</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>CaptureHeader</name>
    <message>
        <location filename="../core/record/capture_header.cpp" line="+127"/>
        <source>line %1 of the capture header is not a key=value entry</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CaptureReader</name>
    <message>
        <location filename="../core/record/capture_reader.cpp" line="+43"/>
        <source>Cannot open %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+66"/>
        <source>not an ImuDesk capture file (it does not start with IMUDCAP1); raw byte dumps are read by &apos;imudesk-cli decode&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>capture format version %1 is newer than this ImuDesk reads (%2); update ImuDesk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the capture header claims %1 bytes (at most %2): the file is damaged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file ends inside the capture header: nothing was recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the capture header&apos;s CRC does not match: the file is damaged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+59"/>
        <location line="+31"/>
        <source>the file ends inside a chunk at offset %1 (recording was interrupted); everything before it was read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-21"/>
        <source>damaged chunk at offset %1 (bad framing); skipped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>damaged chunk at offset %1 (bad length); skipped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>damaged chunk at offset %1 (CRC mismatch); skipped</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CaptureWriter</name>
    <message>
        <location filename="../core/record/capture_writer.cpp" line="+95"/>
        <source>Cannot create the capture file %1: %2. Choose a folder you can write to.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Cannot write the capture file %1: %2. Check the free disk space.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Recording stopped: the disk cannot keep up (more than %1 MB waiting to be written). Record to a faster disk.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+98"/>
        <source>Recording stopped: writing %1 failed (%2). Everything up to that point is in the file; free some disk space and record again.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ConfigProfile</name>
    <message>
        <location filename="../core/settings/config_profile.cpp" line="+55"/>
        <source>the profile is larger than %1 KiB: not an ImuDesk profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the profile is not valid JSON (%1 at byte %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the profile must be a JSON object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>not an ImuDesk profile (&quot;format&quot; must be &quot;imudesk-profile&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>profile version %1 is not supported (this ImuDesk reads version %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>&quot;device&quot; must be an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>&quot;settings&quot; must be an object of &quot;KEY&quot;: &quot;VALUE&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>too many settings (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown setting &apos;%1&apos; in the profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the value of %1 must be a string</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>cannot read %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 is larger than %2 KiB: not an ImuDesk profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CsvCaptureConverter</name>
    <message>
        <location filename="../core/record/csv_capture_converter.cpp" line="+21"/>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+39"/>
        <source>Writing %1 failed: %2. Check the free disk space.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FamilyDetector</name>
    <message>
        <location filename="../core/device/family_detector.cpp" line="+126"/>
        <source>neither a HiPNUC module nor an HEC495 answered on %1 at %2 baud: check the power, the wiring and that no other program holds the port</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>FileAnalysis</name>
    <message>
        <location filename="../core/record/file_analysis.cpp" line="+36"/>
        <source>Analysis cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+9"/>
        <source>%n damaged chunk(s) were skipped</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (neither a capture file nor a vendor HI91 CSV)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 malformed lines in all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 holds no IMU frames to analyse</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>HEC495</name>
    <message>
        <location filename="../core/protocol/can/hec495_can.cpp" line="+253"/>
        <source>node ID = %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN baud = %1 bit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDO mode = %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>heartbeat = %1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>start PDO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>stop PDO</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PDO rate = %1 Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>work mode = 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>object 0x%1 = %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>HipnucWrites</name>
    <message>
        <location filename="../core/protocol/modbus/hipnuc_writes.cpp" line="+103"/>
        <source>save the configuration to flash</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>restore the factory settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>reset the module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>set the baud rate to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>set the node ID to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>switch to 9-axis mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>switch to 6-axis mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancel auto-levelling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>level once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set the mounting (URFR value %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>write %1 to register 0x%2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>IntelHexLoader</name>
    <message>
        <location filename="../core/protocol/ihex/intel_hex_loader.cpp" line="+37"/>
        <source>line %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the file is %1 bytes, more than the %2 bytes a firmware file may have</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>data after the end-of-file record of line %1; the file is damaged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>a record must start with &apos;:&apos;; this is not an Intel HEX file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the record is too short or has an odd number of hex digits; the file is truncated or damaged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&apos;%1&apos; is not a hex digit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the record says %1 data bytes but holds %2; the file is truncated or damaged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>checksum error (record says %1, bytes give %2); the file is damaged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the record runs past the 4 GiB address space</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>an end-of-file record must have no data and address 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>an extended address record must have 2 data bytes and address 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a start address record must have 4 data bytes and address 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown record type %1 (Intel HEX has types 00 to 05)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the file is empty; choose the firmware&apos;s .hex file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file ends without an end-of-file record (type 01); it is truncated, download it again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the file holds no data records</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the record writes %1, which line %2 already wrote (overlapping records); the file is damaged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the image spans %1 bytes from %2, more than %3; the addresses are wrong or this is not a firmware for this device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>the file is empty; choose the firmware&apos;s .bin file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the file is %1 bytes, more than %2; this is not a firmware for this device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image runs past the 4 GiB address space; check the start address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>cannot read %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 is %2 bytes, more than the %3 bytes a firmware file may have</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a .bin file has no address: give its start address (e.g. 0x8000)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>J1939</name>
    <message>
        <location filename="../core/protocol/can/j1939_config.cpp" line="+102"/>
        <source>PGN %1 interval</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>write %1 = %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>save configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>factory defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>trigger PGN %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>trigger</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>CAN baud code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>output enable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inclinometer X sign</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>inclinometer Y sign</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attitude reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>firmware version</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>register 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>write %1 = %2 (status %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read %1 -&gt; %2 (status %3)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>KbootClient</name>
    <message>
        <location filename="../core/firmware/kboot_client.cpp" line="+58"/>
        <source>%1: only damaged bytes arrived (%2 bytes skipped, %3 CRC errors); the line is noisy or the baud is wrong. Run the update again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: the bootloader did not answer; check the cable and power, then run the update again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <source>no bootloader answered %1 pings; check the port and baud rate, power-cycle the module and run the update again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>command 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+140"/>
        <source>no ACK for %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-128"/>
        <source>the bootloader aborted %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the bootloader refused %1 %2 times (NAK: damaged on the way); check the cable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>response to command 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>no %1 within %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>malformed %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+20"/>
        <source>the bootloader answered command 0x%1 instead of 0x%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-14"/>
        <location line="+21"/>
        <source>the bootloader refused command 0x%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-14"/>
        <source>unexpected response 0x%1 to command 0x%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+69"/>
        <source>data packet %1 (bytes %2..%3 at 0x%4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>the bootloader aborted the transfer at %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the bootloader ended the transfer at %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>data packet %1 was refused %2 times (NAK); the line is damaging data. Check the cable and run the update again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>cancelled after %1 of %2 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>the bootloader offers %1 bytes instead of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>reading back stopped after %1 of %2 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>cancelled while reading back</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>KbootStatus</name>
    <message>
        <location filename="../core/protocol/kboot/status_code.cpp" line="+55"/>
        <source>success</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the operation failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the target is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a value is out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>an argument is invalid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader timed out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no transfer is in progress</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the length is not a multiple of the flash unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the address or length is not aligned to a flash sector</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the address is outside the flash</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>flash access error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the region is protected (e.g. the bootloader)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the flash command failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown flash property</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>wrong erase key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the region is execute-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader does not know this command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the command is refused while the chip is secured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the data phase was aborted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ping error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no response</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no response expected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader does not support this command</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the address range is invalid for this memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading the memory failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing the memory failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the flash was not erased before writing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the bootloader does not know this property</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>the property is read-only</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid property value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check passed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check inactive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check invalid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>application CRC check range out of range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no ping response</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid packet type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>packet CRC error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no command response</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unknown status %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2): %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>LinkFactory</name>
    <message>
        <location filename="../ui/link_factory.cpp" line="+42"/>
        <source>Simulated HEC495</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>HEC495 on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Disconnect first, then connect to the compass.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Compass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Compass settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The simulated compass could not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+22"/>
        <source>The simulated Modbus device could not start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Simulated HEC495 (Modbus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated HI14 (Modbus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1, Modbus node %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Disconnect first, then connect to the Modbus device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+23"/>
        <source>The simulated CAN device could not start on %1:%2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>CAN %1:%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Disconnect first, then connect to the CAN bus.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>CAN frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>CAN configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1 cannot be read. Check that the file exists and that you may read it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Replay of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Disconnect first, then open the capture.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Replay</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ModbusSimulator</name>
    <message>
        <location filename="../core/sim/modbus_simulator.cpp" line="+46"/>
        <source>The simulated Modbus device could not open %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>MountingChoice</name>
    <message>
        <location filename="../core/settings/mounting_choice.cpp" line="+69"/>
        <source>IMU X and IMU Y cannot both point %1 / %2: they must be at right angles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>IMU X %1, IMU Y %2, IMU Z %3 is left-handed or not at right angles: with X %1 and Y %2, Z points %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>no URFR code for this mounting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <source>IMU X %1, IMU Y %2, IMU Z %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PtyBridge</name>
    <message>
        <location filename="../core/sim/pty_bridge.cpp" line="+29"/>
        <source>Cannot open a pseudo-terminal: %1</source>
        <translation type="unfinished">无法打开伪终端：%1</translation>
    </message>
    <message>
        <location line="+65"/>
        <source>Cannot create a pipe: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>PtySimulator</name>
    <message>
        <location filename="../core/sim/pty_simulator.cpp" line="+263"/>
        <source>Cannot open a pseudo-terminal: %1</source>
        <translation>无法打开伪终端：%1</translation>
    </message>
</context>
<context>
    <name>RegisterMap</name>
    <message>
        <location filename="../core/protocol/modbus/register_map.cpp" line="+19"/>
        <source>Control: 0 saves the configuration to flash, 1 restores factory settings, 0xFF resets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Baud rate code: 0=4800 1=9600 2=19200 3=38400 4=57600 5=115200 6=230400 7=460800 8=921600</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Modbus node ID, 1-128; takes effect at once</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>0: 6-axis (relative heading, 0 at power-up), 1: 9-axis (magnetic, absolute heading)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Acceleration Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular rate X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular rate Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular rate Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll (R_H high word, R_L low word)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch (P_H high word, P_L low word)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw (Y_H high word, Y_L low word)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temperature</source>
        <translation type="unfinished">温度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pressure (PRS_H high word, PRS_L low word)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion W</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion Y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inclinometer X angle (dual axis: +-180; single axis: 0-360)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inclinometer Y angle (dual axis: +-90; single axis: reserved)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ship heave displacement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ship heave period</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device name (ASCII, 8 registers)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Software version (152 = V1.52)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bootloader version (107 = V1.07)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unique serial number (4 registers)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+2"/>
        <source>Auto-level: 2 or 3 levels once (pitch and roll within 15 deg of 0/0 or 0/180), 5 cancels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mounting: the URFR code (0x18 = 024 horizontal, 0x2B = 043, 0x34 = 052, 0x208 = 520, 0x1A5 = 421)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Mounting: 0 horizontal, 1 Y axis down, 2 Y axis up, 3 X axis up, 4 X axis down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+34"/>
        <source>Pitch (X axis) angle, float</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Roll (Y axis) angle, float</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Heading (Z axis) angle, float</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Reply</name>
    <message>
        <location filename="../core/protocol/witlink/reply.cpp" line="+148"/>
        <source>no error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a reply command that the HEC495 manual does not list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a data field of the wrong length for this reply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a BCD value with a digit above 9 or a bad sign nibble</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>a status byte that is neither 00 (success) nor FF (failure)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: invalid reply (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2 deg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>pitch %1 deg, roll %2 deg, heading %3 deg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>pitch %1 deg, roll %2 deg, heading %3 deg, time %4 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>declination %1 deg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1: success</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1: the device reported failure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>calibration saved: fit error %1, %2 points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>calibration point collected: %1 points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>address %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>unknown reply</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SDO</name>
    <message>
        <location filename="../core/protocol/can/sdo.cpp" line="+11"/>
        <source>toggle bit not alternated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO protocol timed out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>command specifier not valid or unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>out of memory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>unsupported access to an object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attempt to read a write-only object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attempt to write a read-only object</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>object does not exist in the object dictionary</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data type does not match, length of service parameter does not match</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>sub-index does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>invalid value for parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>value of parameter written too high</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>value of parameter written too low</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>general error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data cannot be transferred or stored to the application</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>data cannot be transferred because of the present device state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>abort code 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+122"/>
        <source>SDO write %1 = %2 (%3 bytes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SDO segmented write %1, %2 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO segment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO write %1 confirmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO segment confirmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO read %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO read %1 -&gt; %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SDO read %1: segmented, %2 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SDO abort %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>SDO command 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/protocol/can/sdo_segmented_download.cpp" line="+60"/>
        <source>the device aborted the transfer: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>the device confirmed a segment with the wrong toggle bit</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SerialByteLink</name>
    <message>
        <location filename="../core/firmware/serial_byte_link.cpp" line="+25"/>
        <source>cannot open %1: %2 (is another program using it, or do you lack permission? Close it or join the dialout group)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+31"/>
        <location line="+24"/>
        <source>the port %1 is not open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-18"/>
        <source>writing to %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>writing to %1 stalled: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>reading from %1 failed: %2 (was the device unplugged?)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SettingCatalog</name>
    <message>
        <location filename="../core/settings/setting_catalog.cpp" line="+22"/>
        <source>Output of this message on this port: off, every period (ONTIME 0.001 s = 1 kHz .. 1 s = 1 Hz) or on each SYNC_IN/PPS rising edge (ONMARK 1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Serial baud rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>SERIALCONFIG: the UART switches at once; ImuDesk follows and confirms with LOG VERSION. v1.7.1: 4800 .. 921600; v1.6.6: 9600, 115200, 256000, 460800, 921600.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Data output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LOG ENABLE / LOG DISABLE: all data frames on or off. Output is enabled again after every start.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>HI91 output (float IMU frame)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI92 output (integer IMU frame)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI81 output (INS frame)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI83 output (variable frame)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NMEA GGA output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NMEA RMC output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>NMEA SXT output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI83 fields (data_bitmap)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>LOG HI83 MAP: one bit per data segment (bit 0 acc, 1 gyr, 2 mag, 3 Euler, 4 quaternion, 5 time us, 6 UTC, 7 pressure, ...); default 0x000000FF.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Working mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG ATT MODE: 0 VRU (6-axis), 1 AHRS (9-axis, magnetometer aided; calibrate the magnetometer first, avoid near motors and indoors), 4 humanoid robot (v1.7.1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Mounting (URFR)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG IMU URFR: which sensor direction each user axis is (code ABC, 24 right-handed codes; 24 = X right, Y forward, Z up). Firmware below 1.7.1 takes the nine numbers of the matrix C with X_B = C * X_U.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>World frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG IMU COORD: 0 East-North-Up (ENU, default), 4 North-West-Up (NWU).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>PMUX1 pin (SYNC_IN/PPS input)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PMUX2 pin (SOUT sync output)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PMUX3 pin (status LED)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CONFIG PMUXn IOm: the IO pin that carries this function (defaults PMUX1 IO1, PMUX2 IO2, PMUX3 IO5). Not every IO is brought out on every product.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>SOUT divider</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG PMUX2 DIV: one SOUT pulse every N frames (1 .. 1000, default 1): at 100 Hz output, 5 gives 20 Hz pulses for a camera.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Background magnetometer calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG IMU_EN_MCAL (v1.6.6): 1 calibrates the magnetometer in the background (factory default), 0 stops it; SAVECONFIG keeps it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Heading reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sets the current heading to 0. Keep the device still while it runs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Relative level (zero pitch and roll)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Makes the current pitch and roll the zero, whatever the tilt (no check). Keep the device still; ATT RST 5 undoes it; SAVECONFIG keeps it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Automatic levelling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Only when nearly level: pitch and roll both below 5 deg levels to 0/0, pitch below 5 deg and roll near 180 deg levels to 0/180; otherwise refused (ERR). Keep the device still. Permanent: ATT RST 5 does not undo it, only a factory reset does.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Cancel relative level</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clears the relative pitch/roll zero of ATT RST 2 and returns to absolute angles.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Set heading (v1.6.6)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CONFIG YAW MODE DEG: MODE 1 sets the heading to DEG (absolute), MODE 0 adds DEG (relative); -180 .. 180 deg; at once, not saved. Value &quot;MODE,DEG&quot;, e.g. 1,16.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save to flash</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Saves every setting to flash so that it survives a reset.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Reboot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Resets the module (same as a power cycle): unsaved settings are lost, saved CONFIG settings take effect.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Factory reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restores the factory settings, saves them and resets: baud 115200, HI91 at 100 Hz, mounting 24, working mode, PMUX pins, output messages and ATT RST 3 levelling are all lost.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+69"/>
        <source>VRU (6-axis)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>AHRS (9-axis, magnetometer aided)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Humanoid robot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>East-North-Up (ENU)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>North-West-Up (NWU)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>On (factory default)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+65"/>
        <location line="+10"/>
        <source>not in the manual for firmware %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-8"/>
        <location line="+10"/>
        <source>%1 has no %2 (v1.7.1 feature table)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1=%2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>a baud rate is a whole number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>firmware below 1.7.1 takes 9600, 115200, 256000, 460800 or 921600</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>supported rates are 4800, 9600, 19200, 38400, 57600, 115200, 230400, 256000, 460800 and 921600</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>use ENABLE or DISABLE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>use a period in seconds (0.001 .. 1, 0 = off), ONMARK or OFF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>use a bitmap such as 0x000000FF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>not one of the documented values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 (%2) is not available on this model or firmware</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>not one of the 24 right-handed URFR codes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the matrix is nine numbers C00,C01,...,C22</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>firmware 1.7.1 takes only the 24 URFR codes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>use a pin IO1 .. IO%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>use a whole number %1 .. %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>unknown setting kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+23"/>
        <location line="+43"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 takes no value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>YAW needs MODE,DEG (MODE 0 relative or 1 absolute, DEG -180 .. 180), e.g. YAW=1,16</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>YAW: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+33"/>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-31"/>
        <source>on SYNC_IN pulse (ONMARK 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 Hz (%2 s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+34"/>
        <source>%1 (%2)</source>
        <translation type="unfinished">%1（%2）</translation>
    </message>
    <message>
        <location line="-30"/>
        <source>matrix %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>enabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>disabled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+45"/>
        <source>after SAVECONFIG and a reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at once; SAVECONFIG keeps it after a reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>at once; not saved (enabled again after every start)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>LOG COMCONFIG: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>magnetometer aiding</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>user attitude calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IO pin mapping (PMUX)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>UpdateFlow</name>
    <message>
        <location filename="../core/firmware/update_flow.cpp" line="+35"/>
        <location line="+196"/>
        <location line="+174"/>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-362"/>
        <source>idle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>checking the image</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>identifying the module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>entering the bootloader</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>contacting the bootloader</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>reading the bootloader&apos;s properties</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>erasing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>writing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>verifying</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>restarting the module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>confirming the new version</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation type="unfinished">已取消</translation>
    </message>
    <message>
        <location line="+28"/>
        <source>the image is empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the image starts at %1, which is not a multiple of 4; the bootloader writes whole words</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the image starts at %1, below the application area at %2 (that is the bootloader); this is not an application image for this module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image ends at %1, beyond the end of the flash at %2; it does not fit this module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the image (%1..%2) is outside the module&apos;s flash (%3..%4, %5 bytes reported by the bootloader)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image has %1 bytes, the module&apos;s flash only %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the image starts at %1, which is not on a flash sector boundary (sectors of %2 bytes); the erase would destroy the bytes before it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the image starts at %1, below the application area at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+84"/>
        <source>reading the maximum packet size failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>reading the flash size failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the bootloader reports a maximum packet size of %1 bytes; it cannot take data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the bootloader reports no flash</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bootloader: max packet %1 bytes, flash %2 bytes from %3, sectors of %4 bytes, bootloader version %5, KBOOT %6%7.%8.%9</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>refused before contacting the module: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>image: %1 bytes at %2, CRC-32 %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>module %1, firmware %2, bootloader %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the module is already in its bootloader (an earlier update was interrupted); run the update again and allow finishing it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the module is already in its bootloader: an earlier update was interrupted; finishing it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>nothing answered at %1 baud: neither the application (LOG VERSION) nor the bootloader (ping). Check the port, the baud rate and the power</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>cancelled; the module was not changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the module did not enter its bootloader: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bootloader answers: protocol %1%2.%3.%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <location line="+16"/>
        <source>could not restart the module: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-15"/>
        <source>refused before erasing: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>cancelled before erasing; the module was not changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>erasing %1 bytes at %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>refused before erasing: %1; the module was not changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>erasing failed: %1. The module stays in its bootloader; run the update again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>cancelled while writing (%1). The module stays in its bootloader without a valid application; run the update again to finish it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>writing failed: %1. The module stays in its bootloader; run the update again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 bytes written in %2 s (%3 bytes/s, %4 NAK, %5 packets resent)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>cancelled while verifying; the module stays in its bootloader; run the update again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the image was written but cannot be verified: the bootloader does not offer ReadMemory (%1). The module was not restarted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>verifying failed: %1. Run the update again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>verification failed at %1: wrote %2, read %3. Run the update again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>verified: %1 bytes read back and compared</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>the image is written and verified, but the restart failed: %1. Power-cycle the module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>the image is written and verified, but the application did not answer LOG VERSION within %1 s after the restart; the image may not be a firmware for this module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>updated: firmware %1 → %2, %3 bytes verified by read-back</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>VendorCsvImporter</name>
    <message>
        <location filename="../core/record/vendor_csv_importer.cpp" line="+76"/>
        <source>Cannot open %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>line %1 is longer than %2 characters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>line %1 is not the vendor&apos;s HI91 CSV header (it starts with &quot;%2&quot;)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the header has no %1 column</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>line %1: the first column is &quot;%2&quot;, not HI91</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>line %1 has %2 columns, the header %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>line %1: %2 is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+23"/>
        <source>the file is empty: no HI91 CSV header</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::device::CanSession</name>
    <message>
        <location filename="../core/device/can_session.cpp" line="+93"/>
        <source>HiPNUC J1939</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HiPNUC CANopen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HEC495 CAN</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>CAN</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+81"/>
        <location line="+7"/>
        <source>register access needs a J1939 device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-6"/>
        <source>read register 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>read register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>write register 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>write register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>SDO read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>SDO write</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>0x%1 is not a data PGN</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the interval must be %1 to %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read back the interval</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>PGN %1 interval %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set the interval</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>TPDO channel 0..5 and a period of 0..65535 ms, please</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read back the TPDO period</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TPDO%1 period %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set the TPDO period</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the HEC495 has one PDO rate: use setHec495Rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+66"/>
        <location line="+27"/>
        <location line="+33"/>
        <source>the protocol is not known yet: choose it or wait for traffic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-120"/>
        <source>the HEC495 rate code is 0 (off) to 6 (100 Hz)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>SYNC mode needs a CANopen device and a TPDO channel 0..5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>read back the transmission type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>TPDO%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>SYNC mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>asynchronous mode</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>set the transmission type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the heartbeat needs a CANopen or HEC495 device and 0..65535 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>read back the heartbeat period</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>heartbeat %1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>set the heartbeat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>the node ID must be 1..127</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>traffic from node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>node ID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <location line="+8"/>
        <location line="+89"/>
        <source>reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-96"/>
        <location line="+5"/>
        <location line="+8"/>
        <source>set the node ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-12"/>
        <location line="+5"/>
        <location line="+25"/>
        <location line="+2"/>
        <source>save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-21"/>
        <source>traffic from node %1 (power-cycle the HEC495 now)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>HiPNUC modules support 125000, 250000, 500000, 800000 and 1000000 bit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bit rate %1 (saved; takes effect after a reset: reopen the session at that rate)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+2"/>
        <location line="+8"/>
        <source>set the bit rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-2"/>
        <source>the HEC495 supports 10000 to 500000 bit/s (see its manual&apos;s table)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bit rate %1 (takes effect after a power cycle: reopen the session at that rate)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>attitude reset mode 1, 2, 3 or 5, please</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>attitude reset %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>attitude reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>CANopen zeroing: mode 2 (set zero) or 5 (clear), please</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>zero %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>set zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>attitude reset needs a HiPNUC J1939 or CANopen device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>output on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>output off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>output enable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>NMT</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMT start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>NMT stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>&quot;%1&quot; needs a HiPNUC J1939 or CANopen device (the HEC495 saves at once)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>save configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>factory defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>a one-shot trigger needs a J1939 device and a data PGN</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>trigger</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>trigger PGN %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::device::CanWorker</name>
    <message>
        <location filename="../core/device/can_worker.cpp" line="+103"/>
        <source>no answer from node %1 to &quot;%2&quot; within %3 ms: check the node ID, the bit rate and the wiring</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+33"/>
        <source>opening %1:%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the CAN plugin &quot;%1&quot; is not installed (available: %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cannot create CAN interface %1:%2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>connected to %1:%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the CAN interface closed; received data is kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>cannot open CAN interface %1:%2: %3 (check the interface name, that it is up, and your permissions)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <location line="+4"/>
        <source>the session was closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>CAN interface error: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>could not send frame %1: the CAN interface is not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+48"/>
        <source>boot-up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>heartbeat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>SDO scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+33"/>
        <source>too many requests are waiting; try again when they are done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>could not send &quot;%1&quot;: the CAN interface is not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>the device refused &quot;%1&quot; (status %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>the device aborted &quot;%1&quot;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>the device refused &quot;%1&quot;: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>&quot;%1&quot; read back %2, expected %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>%1: done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::device::Hec495Session</name>
    <message>
        <location filename="../core/device/hec495_session.cpp" line="+94"/>
        <source>the declination must be between -99.9 and 99.9 degrees (got %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>the HEC495 supports 2400, 4800, 9600, 19200 and 115200 baud (got %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the output rate must be 0 (question/answer), 5, 10, 15, 25, 50 or 100 Hz (got %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the output content must be 0 to 3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>the address must be 0 to 255 (got %1)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::device::Hec495Worker</name>
    <message>
        <location filename="../core/device/hec495_worker.cpp" line="+166"/>
        <source>no HEC495 answered on %1 at %2 baud: check the wiring (RS-232 TXD/RXD or RS-485 A/B), the power, the baud rate and the module address (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>any supported</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>the connection was closed</source>
        <translation type="unfinished">连接已关闭</translation>
    </message>
    <message>
        <location line="+55"/>
        <source>the request&apos;s data is longer than a Witlink frame can carry</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>the port is not open</source>
        <translation type="unfinished">串口未打开</translation>
    </message>
    <message>
        <location line="+46"/>
        <source>writing to the port failed</source>
        <translation type="unfinished">向串口写入失败</translation>
    </message>
    <message>
        <location line="+38"/>
        <source>no reply to &quot;%1&quot; after %2 attempts of %3 ms (check the baud rate and the module address; an RS-485 module that streams may miss commands: set question/answer mode)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+148"/>
        <source>the module answered with an invalid reply: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>the module reported failure (FF) for &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>the module streams: identified without a request</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::device::ModbusSession</name>
    <message>
        <location filename="../core/device/modbus_session.cpp" line="+107"/>
        <source>ILLEGAL FUNCTION (01): the device does not support this request at %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ILLEGAL DATA ADDRESS (02): %1 does not exist on this device or cannot be accessed this way (write-only or read-only). Check the register map of the device&apos;s manual.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>ILLEGAL DATA VALUE (03): the device refused the value or count for %1. Check the register&apos;s range.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>SERVER DEVICE FAILURE (04): the device failed while handling %1. Reset it and try again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SERVER DEVICE BUSY (06): the device is busy; try %1 again later.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Modbus exception %1 at %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../core/device/modbus_worker.cpp" line="+78"/>
        <source>The serial port %1 failed (%2). Check that the adapter is plugged in, then connect again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Cannot open %1: %2. Check the port name and that no other program uses it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+28"/>
        <source>Port open at %1 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+130"/>
        <source>register 0x%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>No reply from node %1 at %2 baud within %3 ms. Check the node ID, the baud rate and parity, and the RS-485 wiring (A/B).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The request to node %1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Reading the identity of node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>Modbus node %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Node %1 at %2 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+61"/>
        <source>Node %1 answers again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+62"/>
        <source>not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>a read takes 1 to 125 registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Not connected: connect first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 is not a valid value for %2 (%3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Register address and value must be 0..65535.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Done: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Written, but reading it back failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Written, but the device reads back %1 instead of %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Read back: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+92"/>
        <source>HEC495 compass (pitch %1 deg)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+26"/>
        <source>answers, identity unreadable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>answers with Modbus exception %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::device::SessionWorker</name>
    <message>
        <location filename="../core/device/session_worker.cpp" line="+125"/>
        <source>the connection was closed</source>
        <translation>连接已关闭</translation>
    </message>
    <message>
        <location line="+31"/>
        <source>automatic reconnection was turned off</source>
        <translation>自动重连已关闭</translation>
    </message>
    <message>
        <location line="+19"/>
        <location filename="../core/device/session_worker_baud.cpp" line="+25"/>
        <location line="+49"/>
        <source>the port is not open</source>
        <translation>串口未打开</translation>
    </message>
    <message>
        <location line="+26"/>
        <source>writing to the port failed</source>
        <translation>向串口写入失败</translation>
    </message>
    <message>
        <location line="+29"/>
        <source>no reply within %1 ms (the device ignores commands it does not know)</source>
        <translation>%1 ms 内无应答（设备不响应它不认识的指令）</translation>
    </message>
    <message>
        <location line="+228"/>
        <source>The device that came back on %1 is a different one (serial %2, before %3). Its data continues in this session.</source>
        <translation>%1 上重新出现的是另一台设备（序列号 %2，之前为 %3）。其数据将继续记录在本会话中。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>disconnected — waiting for the device to come back</source>
        <translation>已断开，正在等待设备重新连接</translation>
    </message>
    <message>
        <location line="+33"/>
        <source>%1 at %2 baud (reconnected)</source>
        <translation>%1，波特率 %2（已重连）</translation>
    </message>
    <message>
        <location line="+143"/>
        <source>Bytes keep arriving on %1 but none of them form a frame: the device probably runs at another baud rate now. Disconnect and connect again with the baud rate set to Auto.</source>
        <translation>%1 上持续收到字节，但无法组成任何数据帧：设备可能已改用其他波特率。请断开连接，并将波特率设为“自动”后重新连接。</translation>
    </message>
    <message>
        <location line="+64"/>
        <source>No HiPNUC device answered on %1 at any baud rate (115200, 921600, 460800, 230400, 256000, 57600, 38400, 19200, 9600, 4800). Check the cable and the power, and that no other program uses the port.</source>
        <translation>%1 上在所有波特率（115200、921600、460800、230400、256000、57600、38400、19200、9600、4800）下都没有 HiPNUC 设备应答。请检查线缆和电源，并确认没有其他程序占用该串口。</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>trying %1 baud</source>
        <translation>正在尝试 %1 波特率</translation>
    </message>
    <message>
        <location line="+54"/>
        <source>%1 at %2 baud</source>
        <translation>%1，波特率 %2</translation>
    </message>
    <message>
        <location filename="../core/device/session_worker_baud.cpp" line="-33"/>
        <source>the device refused SERIALCONFIG %1 (%2) and stays at %3 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <location line="+34"/>
        <source>the device answers at %1 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-29"/>
        <source>the device did not answer at %1 baud; it answers at %2 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>the device answers neither at %1 nor at %2 baud nor at any other rate: check the cable and power-cycle it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>the device does not answer at any baud rate</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::io::SerialTransport</name>
    <message>
        <location filename="../core/io/serial_transport.cpp" line="+26"/>
        <source>Port %1 was not found. Check that the device is plugged in and choose the port again from the list.</source>
        <translation>未找到串口 %1。请检查设备是否已插好，然后从列表中重新选择串口。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Port %1 is in use by another program (a serial terminal, CHCenter or another ImuDesk). Close that program and connect again.</source>
        <translation>串口 %1 正被其他程序占用（串口终端、CHCenter 或另一个 ImuDesk）。请关闭该程序后重新连接。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>No permission to open %1. On Linux add your user to the dialout group (sudo usermod -aG dialout $USER), then log out and in again.</source>
        <translation>没有打开 %1 的权限。在 Linux 上请将当前用户加入 dialout 组（sudo usermod -aG dialout $USER），然后注销并重新登录。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Could not open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <location line="+129"/>
        <source>The connection to %1 was lost (%2). Check the cable; everything received so far is kept.</source>
        <translation>与 %1 的连接已断开（%2）。请检查线缆；已接收的数据都会保留。</translation>
    </message>
</context>
<context>
    <name>imudesk::model::MainStatus</name>
    <message>
        <location filename="../core/model/main_status.cpp" line="+11"/>
        <source>Gyro bias estimate not yet converged: keep the module still for 3-5 s to improve heading accuracy.</source>
        <translation>陀螺零偏估计尚未收敛：请保持模块静止 3-5 s，以提高航向角精度。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic disturbance: the field is disturbed, the magnetometer is not calibrated or the hard-iron environment changed; 9-axis heading may be wrong.</source>
        <translation>磁场干扰：磁场受到干扰、磁力计未校准或硬磁环境发生变化；9 轴航向角可能不准确。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Accelerometer over range now or within the last 2 s.</source>
        <translation>加速度计当前或最近 2 s 内超量程。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyroscope over range now or within the last 2 s.</source>
        <translation>陀螺仪当前或最近 2 s 内超量程。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude accuracy poor (large AHRS filter covariance): keep still for a moment.</source>
        <translation>姿态精度差（AHRS 滤波器协方差较大）：请保持静止片刻。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The device detected that it is static.</source>
        <translation>设备检测到自身处于静止状态。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The magnetometer takes part in heading (9-axis mode).</source>
        <translation>磁力计参与航向解算（9 轴模式）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not synchronised to UTC: system_time is time since power-up.</source>
        <translation>未与 UTC 同步：system_time 为上电以来的时间。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>This frame corresponds to a SYNC_OUT pulse.</source>
        <translation>该帧对应一个 SYNC_OUT 脉冲。</translation>
    </message>
</context>
<context>
    <name>imudesk::models::CanFrameMonitorModel</name>
    <message>
        <location filename="../core/models/can_frame_monitor_model.cpp" line="+32"/>
        <source>Ext</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Std</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source> FD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source> RTR</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source> Tx</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source> Rx</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+38"/>
        <source>CAN-ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cycle time (ms)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Meaning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+132"/>
        <source>cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>writing %1 failed: %2 (is the disk full?)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::models::CommandLogModel</name>
    <message>
        <location filename="../core/models/command_log_model.cpp" line="+88"/>
        <source>waiting</source>
        <translation>等待中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ERR</source>
        <translation>ERR</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>timeout</source>
        <translation>超时</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>cancelled</source>
        <translation>已取消</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not sent</source>
        <translation>未发送</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Time</source>
        <translation>时间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Command</source>
        <translation>指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status</source>
        <translation>状态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reply</source>
        <translation>应答</translation>
    </message>
</context>
<context>
    <name>imudesk::models::LatestValuesModel</name>
    <message>
        <location filename="../core/models/latest_values_model.cpp" line="+144"/>
        <source>Quantity</source>
        <translation>物理量</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <location line="+82"/>
        <source>0 invalid</source>
        <translation>0 解无效</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1 aligning</source>
        <translation>1 对准中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>3 navigating</source>
        <translation>3 组合导航中</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>6 dead reckoning</source>
        <translation>6 惯性递推中</translation>
    </message>
    <message>
        <location line="+23"/>
        <source>none (%1)</source>
        <translation>无 (%1)</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Acceleration %1</source>
        <translation>加速度 %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Angular velocity %1</source>
        <translation>角速度 %1</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Magnetic field %1</source>
        <translation>磁场 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll</source>
        <translation>横滚角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch</source>
        <translation>俯仰角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw</source>
        <translation>航向角</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Quaternion %1</source>
        <translation>四元数 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Air pressure</source>
        <translation>气压</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device time</source>
        <translation>设备时间</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>INS status</source>
        <translation>组合导航状态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Latitude</source>
        <translation>纬度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Longitude</source>
        <translation>经度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Altitude (MSL)</source>
        <translation>海拔高度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Velocity east</source>
        <translation>东向速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Velocity north</source>
        <translation>北向速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Velocity up</source>
        <translation>天向速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heave</source>
        <translation>垂荡</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Surge</source>
        <translation>纵荡</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sway</source>
        <translation>横荡</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclination X</source>
        <translation>X 轴倾角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Inclination Y</source>
        <translation>Y 轴倾角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Status flags</source>
        <translation>状态标志</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Frame type</source>
        <translation>帧类型</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>G</source>
        <translation>G</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deg/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>µT</source>
        <translation>µT</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+4"/>
        <location line="+3"/>
        <source>deg</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="-6"/>
        <source>Pa</source>
        <translation>Pa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+2"/>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>Acceleration along the sensor&apos;s %1 axis, in G (1 G = 9.8 m/s², the vendor&apos;s constant).</source>
        <translation>沿传感器 %1 轴的加速度，单位 G（1 G = 9.8 m/s²，厂商采用的常数）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Angular velocity about the sensor&apos;s %1 axis, in deg/s.</source>
        <translation>绕传感器 %1 轴的角速度，单位 °/s。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Magnetic field along the sensor&apos;s %1 axis, in µT.</source>
        <translation>沿传感器 %1 轴的磁场强度，单位 µT。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll angle, in degrees (Euler angles in the device&apos;s convention, ENU 312 by default).</source>
        <translation>横滚角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch angle, in degrees (Euler angles in the device&apos;s convention, ENU 312 by default).</source>
        <translation>俯仰角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Yaw (heading) angle, in degrees (Euler angles in the device&apos;s convention, ENU 312 by default).</source>
        <translation>航向角，单位 °（设备约定的欧拉角，默认 ENU 312 顺序）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Attitude quaternion, component %1 (body to navigation frame), no unit.</source>
        <translation>姿态四元数的 %1 分量（载体系到导航系），无单位。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Air pressure from the barometer, in Pa.</source>
        <translation>气压计测得的气压，单位 Pa。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Sensor temperature, in °C.</source>
        <translation>传感器温度，单位 °C。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device timestamp in ms: UTC time of day when synchronised, otherwise time since power-up.</source>
        <translation>设备时间戳，单位 ms：与 UTC 同步时为当天的 UTC 时间，否则为上电以来的时间。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Integrated navigation state: 0 invalid, 1 aligning, 3 navigating, 6 dead reckoning.</source>
        <translation>组合导航解状态：0 解无效，1 对准中，3 组合导航中，6 惯性递推中。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Position from integrated navigation, in degrees (south and west negative).</source>
        <translation>组合导航解算的位置，单位 °（南纬和西经为负）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Height above mean sea level, in m.</source>
        <translation>平均海平面以上的高度，单位 m。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Velocity in the east-north-up frame, in m/s.</source>
        <translation>东北天（ENU）坐标系下的速度，单位 m/s。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Ship motion displacement (heave, surge, sway), in m.</source>
        <translation>船舶运动位移（垂荡、纵荡、横荡），单位 m。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Inclinometer angle about the %1 axis, in degrees.</source>
        <translation>倾角仪绕 %1 轴的角度，单位 °。</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>MAIN_STATUS flags set in the latest frame (firmware 1.7.0 and later), then the raw word in hex.</source>
        <translation>最新一帧中置位的 MAIN_STATUS 标志（固件 1.7.0 及以上），括号内为十六进制原始值。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The frame type (packet tag) that carried the latest values, e.g. HI91.</source>
        <translation>携带最新数值的帧类型（数据包标签），例如 HI91。</translation>
    </message>
</context>
<context>
    <name>imudesk::models::RegisterTableModel</name>
    <message>
        <location filename="../core/models/register_table_model.cpp" line="+146"/>
        <source>Address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Access</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Raw</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Value</source>
        <translation type="unfinished">数值</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit</source>
        <translation type="unfinished">单位</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Description</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+23"/>
        <source>%1 is not a valid value for %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::models::SettingsTableModel</name>
    <message>
        <location filename="../core/models/settings_table_model.cpp" line="+61"/>
        <source>unknown setting &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+94"/>
        <source>read the device first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+42"/>
        <source>Setting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Key</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>On the device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>New value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Takes effect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read back by</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::record::ReplayWorker</name>
    <message>
        <location filename="../core/record/replay_worker.cpp" line="+60"/>
        <source>%1: %2. Replaying what is intact.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>%n damaged chunk(s) skipped</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::settings::ConfigurationController</name>
    <message>
        <location filename="../core/settings/configuration_controller.cpp" line="+23"/>
        <source>verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not taken (read back differs)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>refused (ERR)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no reply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>not sent</source>
        <translation type="unfinished">未发送</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>the device has not been read yet (its model and firmware decide which settings exist)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>unknown setting &apos;%1&apos; (settings: %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <location line="+236"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-152"/>
        <source>the device did not tell its model and firmware (LOG VERSION: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>incomplete reply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>LOG COMCONFIG failed (%1): the settings shown may be out of date</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+13"/>
        <location line="+111"/>
        <source>another configuration step is still running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-57"/>
        <location line="+79"/>
        <source>the device answered %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-59"/>
        <source>the device reports %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>nothing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>could not be read back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+31"/>
        <source>unknown action &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::settings::ProfileBatch</name>
    <message>
        <location filename="../core/settings/profile_batch.cpp" line="+50"/>
        <source>cannot connect: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>SAVECONFIG failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>%1=%2 not applied: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>%1=%2: %3 %4</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::sim::CanSimulator</name>
    <message>
        <location filename="../core/sim/can_simulator.cpp" line="+43"/>
        <source>cannot create CAN device %1:%2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>cannot open CAN device %1:%2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+97"/>
        <source>--can needs PLUGIN:INTERFACE, e.g. virtualcan:can0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--protocol must be j1939 or canopen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--device must be hipnuc or hec495</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>--node must be 1..127</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::AnalysisWindow</name>
    <message>
        <location filename="../ui/analysis_window.cpp" line="+27"/>
        <source>Analysis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Channel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Unit</source>
        <translation type="unfinished">单位</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Mean</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Std. dev.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Max</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Frame intervals (device clock)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Allan deviation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>Analysing %1…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+39"/>
        <source>%1: %2 frames over %3 s, output rate %4 Hz, interval %5 ± %6 ms, frames lost %7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>ARW %1 deg/√h</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>VRW %1 m/s/√h</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>bias instability %1 deg/h at τ = %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>bias instability %1 mG at τ = %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Recommended minimum recording length for τ up to %1 s: %2 h</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <location line="+13"/>
        <source>frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-9"/>
        <source>≥%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>interval, ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+19"/>
        <source>τ, s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>σ(τ) (deg/s for gyro, G for acc)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::AttitudeWidget</name>
    <message>
        <location filename="../ui/attitude_widget.cpp" line="+245"/>
        <source>X</source>
        <translation>X</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Y</source>
        <translation>Y</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Z</source>
        <translation>Z</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N</source>
        <translation>N</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>E (x)</source>
        <translation>E (x)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>N (y)</source>
        <translation>N (y)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>U (z)</source>
        <translation>U (z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+351"/>
        <source>ENU 3-1-2</source>
        <translation>ENU 3-1-2</translation>
    </message>
    <message>
        <location line="-349"/>
        <source>N (x)</source>
        <translation>N (x)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>E (y)</source>
        <translation>E (y)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>D (z)</source>
        <translation>D (z)</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+347"/>
        <source>NED 3-2-1</source>
        <translation>NED 3-2-1</translation>
    </message>
    <message>
        <location line="-345"/>
        <source>No attitude yet</source>
        <translation>尚无姿态数据</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Roll</source>
        <translation>横滚角</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pitch</source>
        <translation>俯仰角</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Yaw</source>
        <translation>航向角</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Heading</source>
        <translation>方位角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Drag to turn the view, double-click to reset it</source>
        <translation>拖动以旋转视图，双击以复位</translation>
    </message>
    <message>
        <location line="+351"/>
        <source>Reset view</source>
        <translation>复位视图</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::BandwidthCalculator</name>
    <message>
        <location filename="../ui/bandwidth_calculator.cpp" line="+33"/>
        <source>Baud rate:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HI83 fields (MAP):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Message</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bytes per frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Highest usual rate at this baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source> Hz</source>
        <translation type="unfinished"> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+65"/>
        <source>%1 Hz</source>
        <translation type="unfinished">%1 %2 Hz {1 ?}</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>not even 1 Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 of %2 bytes/s (%3 % of the link)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::BusConnect</name>
    <message>
        <location filename="../ui/bus_connect_dialog.cpp" line="+23"/>
        <source>Connect</source>
        <translation type="unfinished">连接</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CanConfigPanel</name>
    <message>
        <location filename="../ui/can_config_panel.cpp" line="+30"/>
        <location line="+2"/>
        <location line="+1"/>
        <location line="+1"/>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-4"/>
        <source>SYNC mode (TPDO sent on each SYNC)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send SYNC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Output on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Factory defaults…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scan nodes 1–127</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <location line="+3"/>
        <location line="+3"/>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-2"/>
        <source>periodic SYNC off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 kbit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heading reset (J1939 1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Set relative zero (2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto level (J1939 3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear zero (5)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Protocol:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output period:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SYNC:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Heartbeat:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Node ID:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CAN bit rate:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Settings:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Discovery:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>SYNC mode on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>SYNC mode off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>heartbeat</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>node ID %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>bit rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>output on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>output off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Factory defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore the module&apos;s default user settings? It saves and resets itself.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>factory defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Scan cancelled; nodes answering so far: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <location line="+1"/>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Scan finished; nodes answering SDO: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Node %1 (%2, %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>no session</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>detecting…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>TPDO%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>PDO %1 Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>PDO off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>%1 every %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>→ %1 …</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>✓ %1: confirmed (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>✗ %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CanConnectDialog</name>
    <message>
        <location filename="../ui/bus_connect_dialog.cpp" line="+99"/>
        <source>Connect over CAN</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The Qt CAN plugin of the adapter: socketcan for Linux CAN interfaces, peakcan for PEAK adapters, virtualcan for a bus inside this computer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>P&amp;lugin:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>The interface of the plugin, e.g. can0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Interface:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Keep the interface&apos;s setting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 kbit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bit rate of the bus; HiPNUC modules default to 500 kbit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Bit rate:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Detect from the traffic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>HEC495 compass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;rotocol:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>First that sends</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>The node ID (CANopen) or source address (J1939) to follow</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Node:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>1.7.x (node-ID object 0x209C)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>1.6.6 (node-ID object 0x20A0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HiPNUC CANopen firmware: where it keeps its node ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Firmware:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start a simulated device on this bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>A simulated module of the chosen protocol answers on the bus (use the virtualcan plugin to try it without hardware)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CanMonitorWidget</name>
    <message>
        <location filename="../ui/can_monitor_widget.cpp" line="+21"/>
        <source>Clear</source>
        <translation type="unfinished">清空</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Export CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Extended</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send</source>
        <translation type="unfinished">发送</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Filter: ID or meaning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pause</source>
        <translation type="unfinished">暂停</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>ID (hex)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>data (hex bytes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+43"/>
        <source>%1 frames, %2 IDs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source> — paused (%1 frames not shown)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source> — %1 frames of IDs beyond the %2-row limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>The ID must be hexadecimal, 0 to 1FFFFFFF.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>The ID must be hexadecimal, 0 to 7FF (tick Extended for 29-bit IDs).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>The data must be pairs of hexadecimal digits, e.g. 2B 00 18 05 0A 00 00 00.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A CAN FD frame carries at most 64 bytes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>A classic CAN frame carries at most 8 bytes (tick FD for more).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Saved %1 IDs to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Export CAN frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>CSV files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ChartPanel</name>
    <message>
        <location filename="../ui/chart_panel.cpp" line="+66"/>
        <source>&amp;Time axis:</source>
        <translation>时间轴(&amp;T)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Device clock</source>
        <translation>设备时钟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Host arrival time</source>
        <translation>主机接收时间</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Device clock: the module&apos;s own timestamps, where lost samples show as gaps. Host arrival time: when the samples reached this computer.</source>
        <translation>设备时钟：模块自身的时间戳，丢失的采样显示为间断。主机接收时间：采样到达本计算机的时间。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ChartView</name>
    <message>
        <location filename="../ui/chart_view.cpp" line="+107"/>
        <source>Accelerometer</source>
        <translation>加速度计</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Gyroscope</source>
        <translation>陀螺仪</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetometer</source>
        <translation>磁力计</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Euler angles</source>
        <translation>欧拉角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion</source>
        <translation>四元数</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Air pressure</source>
        <translation>气压</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+14"/>
        <location line="+39"/>
        <source>Temperature</source>
        <translation>温度</translation>
    </message>
    <message>
        <location line="-45"/>
        <source>Acceleration</source>
        <translation>加速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular velocity</source>
        <translation>角速度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field</source>
        <translation>磁场</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angle</source>
        <translation>角度</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion component</source>
        <translation>四元数分量</translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+39"/>
        <source>Pressure</source>
        <translation>气压</translation>
    </message>
    <message>
        <location line="-30"/>
        <source>G</source>
        <translation>G</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deg/s</source>
        <translation>°/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>µT</source>
        <translation>µT</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>deg</source>
        <translation>°</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Pa</source>
        <translation>Pa</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>°C</source>
        <translation>°C</translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Roll</source>
        <translation>横滚角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Pitch</source>
        <translation>俯仰角</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Yaw</source>
        <translation>航向角</translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Acceleration %1</source>
        <translation>加速度 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular velocity %1</source>
        <translation>角速度 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Magnetic field %1</source>
        <translation>磁场 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Quaternion %1</source>
        <translation>四元数 %1</translation>
    </message>
    <message>
        <location line="+40"/>
        <source>Device time (s)</source>
        <translation>设备时间（s）</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Host arrival time (s)</source>
        <translation>主机接收时间（s）</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>%1 min</source>
        <translation>%1 min</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>the chart could not be drawn</source>
        <translation>无法绘制图表</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Could not save the chart as %1: %2</source>
        <translation>无法将图表保存为 %1：%2</translation>
    </message>
    <message>
        <location line="+150"/>
        <source>%1 (%2)</source>
        <comment>quantity (unit)</comment>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Show or hide %1</source>
        <translation>显示或隐藏 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Window:</source>
        <translation>时间窗(&amp;W)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time span shown by this chart</source>
        <translation>此图表显示的时间跨度</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Auto scale</source>
        <translation>自动缩放</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Fit the vertical axis to the data shown; off: use the range on the right</source>
        <translation>使纵轴适应所显示的数据；关闭时使用右侧设定的范围</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lower end of the vertical axis (no unit)</source>
        <translation>纵轴下限（无单位）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Upper end of the vertical axis (no unit)</source>
        <translation>纵轴上限（无单位）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Lower end of the vertical axis, in %1</source>
        <translation>纵轴下限，单位 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Upper end of the vertical axis, in %1</source>
        <translation>纵轴上限，单位 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save as PNG…</source>
        <translation>另存为 PNG…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save this chart as a PNG image</source>
        <translation>将此图表保存为 PNG 图像</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Follow the newest data again</source>
        <translation>重新跟随最新数据</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Freeze this chart; the data keeps being recorded</source>
        <translation>冻结此图表；数据仍会继续记录</translation>
    </message>
    <message>
        <location line="+216"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+135"/>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>%1 %2 %3</source>
        <comment>crosshair read-out: axis, value, unit</comment>
        <translation>%1 %2 %3</translation>
    </message>
    <message>
        <location line="+23"/>
        <location line="+7"/>
        <source>Save Chart as PNG</source>
        <translation>将图表保存为 PNG</translation>
    </message>
    <message>
        <location line="-7"/>
        <source>PNG images (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::CommandLogWidget</name>
    <message>
        <location filename="../ui/command_log_widget.cpp" line="+169"/>
        <source>Copy</source>
        <translation>复制</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy the selected commands as tab-separated text</source>
        <translation>将所选指令复制为制表符分隔的文本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy all</source>
        <translation>全部复制</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy every command as tab-separated text</source>
        <translation>将所有指令复制为制表符分隔的文本</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear</source>
        <translation>清空</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Remove every command from the list</source>
        <translation>从列表中移除所有指令</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ComparisonChart</name>
    <message>
        <location filename="../ui/comparison_chart.cpp" line="+113"/>
        <source>Comparison</source>
        <translation>对比</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Channel:</source>
        <translation>通道(&amp;C)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The quantity compared across the devices</source>
        <translation>在各设备之间对比的物理量</translation>
    </message>
    <message>
        <location line="+5"/>
        <location line="+16"/>
        <source>%1 (%2)</source>
        <comment>quantity (unit)</comment>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="-14"/>
        <source>&amp;Window:</source>
        <translation>时间窗(&amp;W)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Time span shown</source>
        <translation>显示的时间跨度</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Save as PNG…</source>
        <translation>另存为 PNG…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save this chart as a PNG image</source>
        <translation>将此图表保存为 PNG 图像</translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Resume</source>
        <translation>继续</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Follow the newest data again</source>
        <translation>重新跟随最新数据</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Freeze this chart; the data keeps being recorded</source>
        <translation>冻结此图表；数据仍会继续记录</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConfigPanel</name>
    <message>
        <location filename="../ui/config_panel.cpp" line="+137"/>
        <source>OK</source>
        <translation type="unfinished">OK</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1=%2: %3 %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1 done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 failed: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <source>Read all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save to flash</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Reboot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Factory reset…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Mounting…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy as command line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>absolute</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>relative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source> deg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>%1, firmware %2, serial %3 (%4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Not read yet: press Read all.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+34"/>
        <source>! %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>No pending changes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Link: %1 of %2 bytes/s (%3 %) at %4 baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+35"/>
        <source>✗ %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Output too fast for the link</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Apply anyway?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Factory reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Go ahead?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConnectionBar</name>
    <message>
        <location filename="../ui/connection_bar.cpp" line="+149"/>
        <source>SN %1</source>
        <translation>序列号 %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Manufacturer: %1</source>
        <translation>制造商：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>USB ID: %1:%2</source>
        <translation>USB ID：%1:%2</translation>
    </message>
    <message>
        <location line="+41"/>
        <source>&amp;Port:</source>
        <translation>串口(&amp;P)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Serial port of the IMU, or a simulated device that runs inside ImuDesk</source>
        <translation>IMU 所连接的串口，或在 ImuDesk 内部运行的模拟设备</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Refresh</source>
        <translation>刷新</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Scan for serial ports again (the list also refreshes every 2 s)</source>
        <translation>重新扫描串口（列表也会每 2 s 自动刷新）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Baud rate:</source>
        <translation>波特率(&amp;B)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto</source>
        <translation>自动</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Auto tries every HiPNUC baud rate, starting with 115200</source>
        <translation>自动：从 115200 开始依次尝试 HiPNUC 支持的所有波特率</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Disconnect</source>
        <translation>断开</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close the connection (Ctrl+D)</source>
        <translation>关闭连接（Ctrl+D）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Connect</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect to the selected port (Ctrl+K)</source>
        <translation>连接到所选串口（Ctrl+K）</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Simulated %1 compass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated %1 (firmware %2)</source>
        <translation>模拟 %1（固件 %2）</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 (%2)</source>
        <translation>%1（%2）</translation>
    </message>
    <message>
        <location line="+25"/>
        <source>No serial port found</source>
        <translation>未找到串口</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>A simulated device on a pseudo-terminal, driven exactly like hardware</source>
        <translation>运行在伪终端上的模拟设备，操作方式与真实硬件完全相同</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ConsoleWidget</name>
    <message>
        <location filename="../ui/console_widget.cpp" line="+127"/>
        <source>(reply to: %1)</source>
        <translation>（对 %1 的应答）</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>OK</source>
        <translation>OK</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>ERR: %1</source>
        <translation>错误：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Timeout: %1</source>
        <translation>超时：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancelled: %1</source>
        <translation>已取消：%1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Not sent: %1</source>
        <translation>未发送：%1</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Type an ASCII command, e.g. LOG VERSION, and press Enter</source>
        <translation>输入 ASCII 指令（例如 LOG VERSION）后按回车</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Enter sends the command; Up and Down recall earlier commands</source>
        <translation>回车发送指令；上、下方向键调出历史指令</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send</source>
        <translation>发送</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear log</source>
        <translation>清空日志</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::DeviceWorkspace</name>
    <message>
        <location filename="../ui/device_workspace.cpp" line="+251"/>
        <source>New connection</source>
        <translation>新连接</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>%1 on %2</source>
        <translation>%2 上的 %1</translation>
    </message>
    <message>
        <location line="+43"/>
        <source>Disconnect first, then connect to the simulated device.</source>
        <translation>请先断开，再连接模拟设备。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>The simulated device could not start: %1</source>
        <translation>模拟设备无法启动：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Simulated %1 (firmware %2)</source>
        <translation>模拟 %1（固件 %2）</translation>
    </message>
    <message>
        <location line="+130"/>
        <source>Not connected</source>
        <translation>未连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Opening %1…</source>
        <translation>正在打开 %1…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Detecting the baud rate of %1…</source>
        <translation>正在检测 %1 的波特率…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connected</source>
        <translation>已连接</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connection to %1 lost</source>
        <translation>与 %1 的连接已断开</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Disconnected from %1 — waiting for the device to come back</source>
        <translation>已与 %1 断开，正在等待设备重新连接</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Could not connect to %1</source>
        <translation>无法连接到 %1</translation>
    </message>
    <message>
        <location line="+13"/>
        <source>firmware %1</source>
        <translation>固件 %1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>SN %1</source>
        <translation>序列号 %1</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Product: %1</source>
        <translation>产品：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Build: %1</source>
        <translation>构建：%1</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Bootloader: %1</source>
        <translation>引导程序：%1</translation>
    </message>
    <message>
        <location line="+8"/>
        <location line="+8"/>
        <source>%1 baud</source>
        <translation>波特率 %1</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>%1 %2 Hz</source>
        <translation>%1 %2 Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>no frames</source>
        <translation>无数据帧</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>load %1%</source>
        <translation>负载 %1%</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CRC errors %1</source>
        <translation>CRC 错误 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>lost %1</source>
        <translation>丢失 %1</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>skipped %1 B</source>
        <translation>跳过 %1 B</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Received %1 bytes, %2 frames, %3 NMEA sentences.
Errors: %4 CRC, %5 length, %6 payload, %7 NMEA; %8 bytes skipped.
Frames lost (gaps in the device time): %9.
Link load = bytes per second × 10 bits / baud rate.</source>
        <translation>已接收 %1 字节、%2 帧、%3 条 NMEA 语句。
错误：CRC %4 个，长度 %5 个，载荷 %6 个，NMEA %7 个；跳过 %8 字节。
丢失的帧（设备时间中的间断）：%9。
链路负载 = 每秒字节数 × 10 位 / 波特率。</translation>
    </message>
    <message>
        <location line="+48"/>
        <source>Console</source>
        <translation>控制台</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Raw bytes</source>
        <translation>原始字节</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Command log</source>
        <translation>指令日志</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Values and attitude</source>
        <translation>数值与姿态</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Configuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Recording</source>
        <translation type="unfinished">记录</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ExportDialog</name>
    <message>
        <location filename="../ui/export_dialog.cpp" line="+21"/>
        <source>Export %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Vendor CSV (one file per frame type)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Tidy CSV (pandas, PlotJuggler)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>JSON Lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <location line="+5"/>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Format:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>From:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>To:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+65"/>
        <source>Exporting…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+32"/>
        <source>Export cancelled; the partial files were removed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+6"/>
        <source>%n row(s) written to %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::FirmwareUpdateDialog</name>
    <message>
        <location filename="../ui/firmware_update_dialog.cpp" line="+27"/>
        <source>unknown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Firmware update on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Intel HEX (.hex) or raw binary (.bin)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Choose...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>File:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>A .bin file has no addresses: the flash address of its first byte</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Start of a .bin:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>no file chosen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Image:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1, firmware %2, bootloader %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>read when the update starts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Step:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Progress:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Speed:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Update</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <location line="+141"/>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-103"/>
        <source>Choose the firmware</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Firmware (*.hex *.ihex *.bin);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <location line="+5"/>
        <source>refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>%1 bytes from %2 to %3, CRC-32 %4; target model: not recorded in the file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>cancelling after the current packet...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 of %2 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 bytes/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 bytes/s, %2 s left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>%1, firmware %2 (new), bootloader %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Done: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Not updated: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::HeadingDial</name>
    <message>
        <location filename="../ui/heading_dial.cpp" line="+25"/>
        <source>Heading dial</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+30"/>
        <source>%1°</source>
        <translation type="unfinished">%1°</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>no data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>pitch %1°  roll %2°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+34"/>
        <source>N</source>
        <translation type="unfinished">N</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>E</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>S</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>W</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::Hec495SettingsPanel</name>
    <message>
        <location filename="../ui/hec495_settings_panel.cpp" line="+115"/>
        <source>Factory reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Restore the factory settings (9600 baud, address 0, declination 0, question/answer)? The session follows the module to 9600 baud.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Waiting for the module…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+15"/>
        <source>Failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>Magnetic declination</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Baud rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output content</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Module address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Factory reset…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Changes apply at once and are lost at power-off unless saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Question/answer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>%1 Hz</source>
        <translation type="unfinished">%1 %2 Hz {1 ?}</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Default (angles)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Internal data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>All data (read-all record)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NMEA 0183</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::LanguageSwitcher</name>
    <message>
        <location filename="../ui/language_switcher.cpp" line="+52"/>
        <source>Unknown language &quot;%1&quot;; choose one of: %2.</source>
        <translation>未知语言“%1”；请选择以下之一：%2。</translation>
    </message>
    <message>
        <location line="+14"/>
        <source>The %1 translation was not found in %2.</source>
        <translation>在 %2 中未找到 %1 翻译。</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MainWindow</name>
    <message>
        <location filename="../ui/main_window.cpp" line="+288"/>
        <source>Choose a port first.</source>
        <translation>请先选择串口。</translation>
    </message>
    <message>
        <location line="+50"/>
        <source>Could not save the screenshot to %1: %2</source>
        <translation>无法将截图保存到 %1：%2</translation>
    </message>
    <message>
        <location line="+19"/>
        <source>ImuDesk</source>
        <translation>ImuDesk</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>About ImuDesk</source>
        <translation>关于 ImuDesk</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;A bench tool for HiPNUC IMU modules: live values, the ASCII command console and simulated devices.&lt;/p&gt;&lt;p&gt;Built with Qt %2.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;ImuDesk %1&lt;/h3&gt;&lt;p&gt;HiPNUC IMU 模块测试工具：实时数值、ASCII 指令控制台和模拟设备。&lt;/p&gt;&lt;p&gt;基于 Qt %2 构建。&lt;/p&gt;</translation>
    </message>
    <message>
        <location line="+18"/>
        <source>ImuDesk – IMU bench tool</source>
        <translation>ImuDesk – IMU 测试工具</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 – %2</source>
        <translation>%1 – %2</translation>
    </message>
    <message>
        <location line="+49"/>
        <source>Save screenshot</source>
        <translation>保存截图</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>PNG images (*.png)</source>
        <translation>PNG 图像 (*.png)</translation>
    </message>
    <message>
        <location line="+63"/>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Device</source>
        <translation>设备(&amp;D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;New connection tab</source>
        <translation>新建连接标签页(&amp;N)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Open a tab for another device; each tab has its own connection and views</source>
        <translation>为另一台设备打开一个标签页；每个标签页都有独立的连接和视图</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Close tab</source>
        <translation>关闭标签页(&amp;C)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save &amp;screenshot…</source>
        <translation>保存截图(&amp;S)…</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Connect</source>
        <translation>连接(&amp;C)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect to the port chosen in the connection bar</source>
        <translation>连接到连接栏中所选的串口</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Disconnect</source>
        <translation>断开(&amp;D)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Send LOG &amp;VERSION</source>
        <translation>发送 LOG &amp;VERSION</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Ask the device for its product name, firmware and serial number</source>
        <translation>查询设备的产品型号、固件版本和序列号</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;About ImuDesk</source>
        <translation>关于 ImuDesk(&amp;A)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Preferences…</source>
        <translation>首选项(&amp;P)…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Compare devices</source>
        <translation>设备对比</translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ModbusConnectDialog</name>
    <message>
        <location filename="../ui/bus_connect_dialog.cpp" line="-121"/>
        <source>Connect over Modbus RTU</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The RS-485 adapter&apos;s serial port, or a simulated device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>%1 (%2)</source>
        <translation type="unfinished">%1（%2）</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Simulated HI14 (Modbus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Simulated HEC495 (Modbus)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Port:</source>
        <translation type="unfinished">串口(&amp;P)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>HiPNUC module</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>HEC495 compass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Which register map the device has</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Device:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Modbus node ID (slave address), 1 to 247; HiPNUC modules default to 80, the HEC495 to 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Node ID:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Baud rate of the RS-485 bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Baud rate:</source>
        <translation type="unfinished">波特率(&amp;B)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>None</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Even</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Odd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;arity:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source> Hz</source>
        <translation type="unfinished"> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How often the sensor registers are read; limited to what the baud rate carries</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>P&amp;olling rate:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Also read the ship-motion registers (heave)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ModbusScanDialog</name>
    <message>
        <location filename="../ui/modbus_scan_dialog.cpp" line="+24"/>
        <source>Scan the Modbus bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Every baud rate (4800 to 921600)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>First node ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Last node ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+10"/>
        <source>Node ID</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Baud</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Cancel scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Use</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+60"/>
        <source>The first node ID must not be above the last.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>Scanning ...</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+28"/>
        <source>Cancelled; %n device(s) found so far.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location line="+2"/>
        <source>No device answered. Check the wiring (A/B), the baud rate and parity, or scan every baud rate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location line="+2"/>
        <source>%n device(s) found.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::MountingPicker</name>
    <message>
        <location filename="../ui/mounting_picker.cpp" line="+28"/>
        <source>Mounting (URFR)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Where do the module&apos;s axes point on the body (right, forward, up)? Pick a picture, a code, or the directions of IMU X and IMU Y. The setting takes effect after SAVECONFIG and a reset.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Code:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>IMU X points:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>IMU Y points:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>IMU Z points:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+75"/>
        <source>(no right-handed mounting)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Command: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::PreferencesDialog</name>
    <message>
        <location filename="../ui/preferences_dialog.cpp" line="+21"/>
        <source>Preferences</source>
        <translation>首选项</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Language</source>
        <translation>语言</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>System language</source>
        <translation>跟随系统</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>The language of the user interface. Takes effect the next time ImuDesk starts.</source>
        <translation>用户界面的语言。下次启动 ImuDesk 时生效。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Language:</source>
        <translation>语言(&amp;L)：</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The new language is used after a restart.</source>
        <translation>新语言在重新启动后生效。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Display</source>
        <translation>显示</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>G (1 G = 9.8 m/s²)</source>
        <translation>G（1 G = 9.8 m/s²）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit of the accelerometer values and chart. Recorded data keeps the device&apos;s unit (G).</source>
        <translation>加速度计数值和曲线的单位。记录的数据保持设备的单位（G）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Acceleration:</source>
        <translation>加速度(&amp;A)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>deg/s</source>
        <translation>deg/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Unit of the gyroscope values and chart. Recorded data keeps the device&apos;s unit (deg/s).</source>
        <translation>陀螺仪数值和曲线的单位。记录的数据保持设备的单位（deg/s）。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Angular &amp;rate:</source>
        <translation>角速度(&amp;R)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>ENU (east, north, up)</source>
        <translation>ENU（东、北、天）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>NED (north, east, down)</source>
        <translation>NED（北、东、地）</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>World frame of the 3D attitude view.</source>
        <translation>三维姿态视图的世界坐标系。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Attitude &amp;frame:</source>
        <translation>姿态坐标系(&amp;F)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> Hz</source>
        <translation> Hz</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>How often charts and values are redrawn (%1 to %2 Hz). Lower rates use less CPU.</source>
        <translation>曲线和数值的刷新频率（%1 至 %2 Hz）。频率越低占用 CPU 越少。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Chart &amp;refresh:</source>
        <translation>曲线刷新(&amp;R)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source> min</source>
        <translation> 分钟</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>The longest time window a chart can show (%1 to %2 minutes).</source>
        <translation>曲线可显示的最长时间窗口（%1 至 %2 分钟）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Chart &amp;history:</source>
        <translation>曲线历史(&amp;H)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Recording</source>
        <translation>记录</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Documents folder</source>
        <translation>文档文件夹</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Where new recordings are written.</source>
        <translation>新记录保存的位置。</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Browse…</source>
        <translation>浏览(&amp;B)…</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>&amp;Folder:</source>
        <translation>文件夹(&amp;F)：</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>File name of a new recording. {product}, {serial}, {date} and {time} are replaced.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>File &amp;pattern:</source>
        <translation>文件名模式(&amp;P)：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Example:</source>
        <translation>示例：</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Connection</source>
        <translation>连接</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Reconnect by itself when an unplugged device comes back</source>
        <translation>拔出的设备重新插入时自动重连(&amp;R)</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>After a cable is pulled, wait for the same device (USB serial number, else port) and reconnect at the last baud rate.</source>
        <translation>线缆拔出后，等待同一设备（按 USB 序列号，否则按端口）重新出现，并以上次的波特率重新连接。</translation>
    </message>
    <message>
        <location line="+59"/>
        <source>Recording folder</source>
        <translation>记录文件夹</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ProfileDialog</name>
    <message>
        <location filename="../ui/profile_dialog.cpp" line="+21"/>
        <source>Configuration profiles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Read device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save device to profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Load profile…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Apply to this device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Setting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Note</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Other ports (comma-separated):</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Apply and save to each</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Serial number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Product</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>Details</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+21"/>
        <source>%1 settings applied and verified.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>%1 of %2 settings verified. %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+25"/>
        <source>read the device first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+6"/>
        <source>Saved %1 settings to %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+17"/>
        <source>Loaded %1 (%2 settings, taken from %3 %4).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+37"/>
        <source>The device already matches the profile.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>OK (%1 changed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+0"/>
        <source>FAILED</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Save profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+8"/>
        <source>ImuDesk profiles (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-1"/>
        <source>Load profile</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RawBytesView</name>
    <message numerus="yes">
        <location filename="../ui/raw_bytes_view.cpp" line="+196"/>
        <source>… %n read(s) or write(s) not shown (the log dropped them before this view caught up) …</source>
        <translation>
            <numerusform>… 有 %n 次读取或写入未显示（在此视图跟上之前，日志已将其丢弃）…</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location line="+3"/>
        <source>… %n byte(s) not shown (more arrived than the view holds) …</source>
        <translation>
            <numerusform>… 有 %n 字节未显示（到达的数据超出视图容量）…</numerusform>
        </translation>
    </message>
    <message>
        <location line="+64"/>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Stop updating the view; the bytes are still recorded</source>
        <translation>停止更新视图；字节仍会继续记录</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Clear</source>
        <translation>清空</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Empty the view</source>
        <translation>清空视图</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy</source>
        <translation>复制</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Copy the selected lines, or everything shown, to the clipboard</source>
        <translation>将所选行（未选择时为全部显示内容）复制到剪贴板</translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Link traffic: time (s), direction (RX from the device, TX to it), byte offset, hex and ASCII</source>
        <translation>链路流量：时间（s）、方向（RX 为来自设备，TX 为发往设备）、字节偏移、十六进制和 ASCII</translation>
    </message>
    <message>
        <location line="+7"/>
        <source>RX %1 bytes, TX %2 bytes</source>
        <translation>RX %1 字节，TX %2 字节</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Paused — %1</source>
        <translation>已暂停 — %1</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RecordingControls</name>
    <message>
        <location filename="../ui/recording_controls.cpp" line="+18"/>
        <source>Record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Folder the capture files are written to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>File name; {date}, {time}, {product} and {serial} are filled in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+14"/>
        <source>Folder:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>File:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+84"/>
        <source>Connect a device before recording.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>The folder %1 does not exist. Choose another one.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+24"/>
        <source>Recording to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+18"/>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+16"/>
        <source>%1:%2:%3</source>
        <translation type="unfinished">%1:%2:%3</translation>
    </message>
    <message numerus="yes">
        <location line="+5"/>
        <source>%n frame(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>imudesk::ui::RegisterBrowser</name>
    <message>
        <location filename="../ui/register_browser.cpp" line="+24"/>
        <source>Modbus registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+20"/>
        <source>03 Read holding registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>06 Write single register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Register address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Send</source>
        <translation type="unfinished">发送</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>Address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+27"/>
        <source>Writing %1 to register 0x%2 ...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+90"/>
        <source>Not connected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Only functions 03 and 06 are supported by these devices.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+12"/>
        <source>count </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+3"/>
        <source>value </source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ReplayControls</name>
    <message>
        <location filename="../ui/replay_controls.cpp" line="+33"/>
        <location line="+64"/>
        <location line="+24"/>
        <source>Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-83"/>
        <source>%1×</source>
        <translation type="unfinished">%1×</translation>
    </message>
    <message>
        <location line="+0"/>
        <source>As fast as possible</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+78"/>
        <source>Pause</source>
        <translation type="unfinished">暂停</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>%1 / %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::SettingValueDelegate</name>
    <message>
        <location filename="../ui/setting_value_delegate.cpp" line="+53"/>
        <source>the value was refused</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>imudesk::ui::StatusFlagsWidget</name>
    <message>
        <location filename="../ui/status_flags_widget.cpp" line="+95"/>
        <source>Status:</source>
        <translation>状态：</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>&lt;b&gt;%1&lt;/b&gt; (bit %2): %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;（位 %2）：%3</translation>
    </message>
    <message>
        <location line="+2"/>
        <source>MAIN_STATUS flags of the latest frame: green = set, grey = clear, outlined = the frame carries no status word (firmware before 1.7.0, or another frame type)</source>
        <translation>最新一帧的 MAIN_STATUS 标志：绿色 = 置位，灰色 = 未置位，仅边框 = 该帧不含状态字（固件低于 1.7.0 或其他帧类型）</translation>
    </message>
</context>
<context>
    <name>imudesk::ui::ToolActions</name>
    <message>
        <location filename="../ui/tool_actions.cpp" line="+85"/>
        <source>&amp;Open capture…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Play a recorded capture through the charts and views, as a live device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Import vendor CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Turn a CSV written by the vendor&apos;s PC tool into a capture and play it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Export capture…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write a capture as vendor CSV, tidy CSV or JSON Lines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Analyze capture…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Statistics, output rate and jitter, lost frames and Allan deviation of a capture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect over &amp;Modbus RTU…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Poll a module or compass on an RS-485 bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Connect over C&amp;AN…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Listen to and configure a J1939, CANopen or HEC495 device on a CAN bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Scan Modbus bus…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Find the node IDs that answer on the bus</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Con&amp;figuration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Every setting of the connected module: read, edit, apply, save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Profiles…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Save the configuration to a file, compare a file with the device, apply it to several</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Output-rate &amp;calculator…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Bytes per second of the chosen outputs against the link&apos;s capacity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Update firmware…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Write a new firmware image to the module, verified by reading it back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>&amp;Record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Show the recording controls of this device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+2"/>
        <source>&amp;Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+35"/>
        <source>%1 could not be imported: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+8"/>
        <source>Open capture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <location line="+22"/>
        <source>Captures (*.imucap);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="-15"/>
        <source>Import vendor CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>CSV files (*.csv);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Save the imported capture as</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Captures (*.imucap)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+7"/>
        <source>Export capture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Analyze capture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location line="+1"/>
        <source>Captures and vendor CSV (*.imucap *.csv);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <location filename="../app/gui/main.cpp" line="+82"/>
        <source>ImuDesk: a bench tool for HiPNUC IMU modules.</source>
        <translation>ImuDesk：HiPNUC IMU 模块测试工具。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>User interface language: zh_CN, zh_TW or en (default: the system&apos;s).</source>
        <translation>界面语言：zh_CN、zh_TW 或 en（默认跟随系统）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Start connected to a simulated device (model MODEL, default HI14) that streams HI91 at 100 Hz.</source>
        <translation>启动后连接到一个以 100 Hz 输出 HI91 的模拟设备（型号 MODEL，默认 HI14）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Firmware of the simulated device: 1.7.1 or 1.6.6 (default 1.7.1).</source>
        <translation>模拟设备的固件版本：1.7.1 或 1.6.6（默认 1.7.1）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Motion of the simulated device: static, spin or tumble (default static).</source>
        <translation>模拟设备的运动方式：static（静止）、spin（旋转）或 tumble（翻滚）（默认 static）。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Start connected to this serial port.</source>
        <translation>启动后连接到此串口。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Baud rate for --port or --simulate (default: detect automatically).</source>
        <translation>--port 或 --simulate 使用的波特率（默认自动检测）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Start connected to a simulated HI14 (firmware 1.7.1) that tumbles slowly through every orientation.</source>
        <translation>启动后连接到一个模拟 HI14（固件 1.7.1），它会缓慢翻滚，经历所有姿态。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Save the main window to this PNG file and quit (see --after).</source>
        <translation>将主窗口保存为此 PNG 文件后退出（参见 --after）。</translation>
    </message>
    <message>
        <location line="+4"/>
        <source>Seconds to wait before --screenshot (default 3).</source>
        <translation>执行 --screenshot 前等待的秒数（默认 3）。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Model to simulate with --simulate (default HI14).</source>
        <translation>--simulate 模拟的型号（默认 HI14）。</translation>
    </message>
    <message>
        <location line="+8"/>
        <source>A model name is only accepted after --simulate.</source>
        <translation>型号名称只能跟在 --simulate 之后。</translation>
    </message>
    <message>
        <location line="+6"/>
        <source>--after needs a number of seconds from 0 to 3600.</source>
        <translation>--after 需要 0 到 3600 之间的秒数。</translation>
    </message>
    <message>
        <location line="+3"/>
        <source>Use either --simulate or --port, not both.</source>
        <translation>--simulate 和 --port 只能二选一。</translation>
    </message>
    <message>
        <location line="+11"/>
        <source>Unsupported baud rate &quot;%1&quot;; use auto or one of: %2.</source>
        <translation>不支持的波特率“%1”；请使用 auto 或以下之一：%2。</translation>
    </message>
    <message>
        <location line="+9"/>
        <source>Invalid firmware version &quot;%1&quot;; use e.g. 1.7.1 or 1.6.6.</source>
        <translation>无效的固件版本“%1”；请使用例如 1.7.1 或 1.6.6。</translation>
    </message>
    <message>
        <location line="+5"/>
        <source>Unknown motion &quot;%1&quot;; use static, spin or tumble.</source>
        <translation>未知的运动方式“%1”；请使用 static、spin 或 tumble。</translation>
    </message>
    <message>
        <location line="+20"/>
        <source>ImuDesk</source>
        <translation>ImuDesk</translation>
    </message>
</context>
</TS>
