<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_GB">
<context>
    <name>tt::ui::AppState</name>
    <message>
        <source>Idle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::MainWindow</name>
    <message>
        <source>About TrueTurn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h2&gt;TrueTurn %1&lt;/h2&gt;&lt;p&gt;Adaptive accuracy control for lathes: run-to-run control of the shaft profile, in-process compensation of boring-bar deflection, feed scheduling and drive corrections.&lt;/p&gt;&lt;p&gt;Qt %2&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TrueTurn — adaptive lathe control</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About TrueTurn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loop: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Loop: %1 — %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no devices connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fault</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>check</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>History: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::PlannedPage</name>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measurements</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reports</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Closed-loop run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start, pause and stop the run-to-run loop; the profile error of the last part against the tolerance band; the correction path; alarms.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No parts measured yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured diameters of every part at the control points, accepted or rejected with the reason, and manual entry for a hand micrometer.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool stiffness table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Boring bars and holders: section, overhang, material, computed and measured stiffness (N/mm), and the cross-feed current-to-force gain k&lt;sub&gt;p&lt;/sub&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibration wizards</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Probe-mandrel linearisation (ADC code to deflection table) and the current-to-force gain k&lt;sub&gt;p&lt;/sub&gt; from known loads.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller tuning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Transport delay z, weights R1 and R2, correction limits, the disturbance model and the resulting LQG gains.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No runs recorded yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Per-part profiles, SPC charts and capability (Cp, Cpk) at the control points, with PDF and CSV export.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gauge micrometer, probe mandrel, drive-current readout and the correction output to the CNC; the built-in simulator is always available.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::SettingsPage</name>
    <message>
        <source>Terminal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Language</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name recorded with every change you apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run history</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
