<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="en_GB">
<context>
    <name>BoringPanel</name>
    <message>
        <source>The drive current read-out is silent or disconnected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The probe mandrel is silent or disconnected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The probe mandrel sends raw codes without a linearisation table: load one on the Calibration page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Taper or contour (or a feed move): the force cannot be read from the current here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The cross slide does not move with the dither: it sticks, or the dither is off.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The dither stroke is too short for this PLC cycle: too few readings at constant speed. Use a longer dither period or a shorter PLC cycle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waiting for a forward and a reverse dither stroke.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Holding the offset at %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CNC does not take the offset: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compensating</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The offset is at its range limit: the deflection is larger than the limit allows.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The offset moves at its rate limit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The offset follows the measured deflection.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No data from the probe mandrel for more than %1 ms.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No valid deflection this cycle.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The device reports: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not answering yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>disconnected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CNC output is %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CNC does not take the offset.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The tool has no stiffness: enter its section and overhang on the Tools page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The tool has no current-to-force gain k_p: calibrate it on the Calibration page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The chosen source has no drive current read-out.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The chosen source has no probe mandrel.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the mandrel&apos;s plane that lies along X.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The offset limit of %1 mm is outside %2 to %3 mm.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The rate limit of %1 mm/s is outside %2 to %3 mm/s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The PLC cycle of %1 ms is outside %2 to %3 ms.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The simulated station runs at a PLC cycle of %1 ms, not %2 ms.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The force estimator&apos;s settings are refused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CNC holds an offset of %1 mm, more than the limit of %2 mm: zero the offset first (tool out of the bore).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The run is refused.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>CornerPlots</name>
    <message>
        <source>Path near the corner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Programmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Without pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contour error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time, ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error, µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Control interval</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corrective pulse on X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corrective pulse on Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pulse, V</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Network training</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Epoch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RMS amplitude error, mV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Training moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Validation moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drift monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured − predicted cost, %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Within the threshold</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last %1 corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retrained</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retraining refused</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>DeviceKinds</name>
    <message>
        <source>Gauge micrometer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Probe mandrel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive-current readout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Correction output to the CNC</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>DeviceSettings</name>
    <message>
        <source>Millimetres</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inches</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Output format</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ASCII data cable (01A+00026.812)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Digimatic, 13 nibbles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Digimatic, hexadecimal text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What the data cable or interface sends.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Instrument unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The unit the micrometer displays; the ASCII format does not say.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Job unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Readings in another unit are refused, never converted silently.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serial port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The port the cable is plugged into, e.g. /dev/ttyUSB0 or COM3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Baud rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bit/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Must match the instrument&apos;s setting.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Data bits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>None</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Even</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Odd</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop bits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not on or off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: a whole number is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a whole number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 is not one of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 is outside %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: a number is required</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not one of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: choose the serial port the device is connected to</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 does not exist on this computer (is the cable plugged in?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: choose a folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the folder %2 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the folder %2 is not writable</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>GCodeOutput</name>
    <message>
        <source>the folder %1 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the folder %1 is not writable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G-code files go to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a G-code file cannot apply a dynamic X offset; use a Modbus correction output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Files written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where the CNC picks up its programs (network share, DNC folder).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>{part} becomes the part number.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nominal diameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Finishing feed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm/rev</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spindle speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rpm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>0 leaves the spindle to the main program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X words</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameters (diameter mode)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radii (radius mode)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write G7/G8</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>For controls that select the X mode by G-code (LinuxCNC).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine Z of the part&apos;s left end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z direction along the part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Towards the chuck is -Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Towards the chuck is +Z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clearance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Correction limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A path with a larger correction is refused, never written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>G-code file</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>LinuxCnc</name>
    <message>
        <source>Host: enter the IP address or name of the LinuxCNC computer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: one word without spaces (the remote shell splits at spaces)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Largest step: must not exceed the largest total</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part program: an absolute path on the LinuxCNC computer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LinuxCNC lathe (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LinuxCNC machines every part; the simulated shaft&apos;s physics is applied to the path LinuxCNC executed and the simulated micrometer measures it; TrueTurn writes the corrections into LinuxCNC between parts.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E-stop on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>idle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>paused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no part program is set for LinuxCNC; the operator runs the parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no corrections were sent for part %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1; X %2 Z %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1: no corrections</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: part %2: %3; nothing written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LinuxCNC takes corrections between parts; a dynamic X offset needs a PLC (Modbus output)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LinuxCNC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>remote shell %1, protocol %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine units</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X %1 Z %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Program units</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inch (G20)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm (G21)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diameter (G7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>radius (G8)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writes verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writes refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read-backs that differed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writes held (machine not ready)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection resets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parts cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parts aborted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Host</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IP address or name of the LinuxCNC computer (its remote shell, linuxcncrsh).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TCP port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>linuxcncrsh --connectpw; sent in clear text.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enable password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>linuxcncrsh --enablepw: the right to command the machine; sent in clear text.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Client name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How TrueTurn introduces itself (one word).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connect timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reply timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A reply, a mode change or an MDI line; the connection is reset without it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Joints to be homed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A lathe: 2 (X and Z).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How the correction reaches the cut</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile: the control-point corrections as numbered parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wear: one diameter correction as the tool&apos;s X wear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First parameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>#500 .. #504 hold the corrections, #505 the part number they are for.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wear entry (tool number)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its X wear is set by G10 L1; the part program applies it with G43.2 H&lt;entry&gt;.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X words of the part program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameters (G7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radii (G8)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Units of the part program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Millimetres (G21)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inches (G20)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Largest step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Largest change of a correction from part to part (radial); larger is never written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Largest total</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Largest correction (radial); larger is never written.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part program on the LinuxCNC computer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Empty: the operator runs the parts; TrueTurn writes between them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TrueTurn presses cycle start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Otherwise the operator presses it after TrueTurn has written the corrections.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LinuxCNC at %1:%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LinuxCNC remote shell (TCP)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Modbus</name>
    <message>
        <source>connecting to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connected to %1; reading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot send the request to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2 polls in a row)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sample refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>polling %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 A, %2 mm/s, %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timeouts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus exceptions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Samples refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polls skipped (previous still running)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polling period</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The PLC cycle of paper 001: 10 to 100 ms.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What is written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Per-point corrections of the next part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dynamic X offset, every PLC cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First correction register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paper 000 controls five points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the part number last</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A handshake: the PLC applies the corrections when the number changes.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part number register (int32)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X offset register</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm per count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Correction limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Larger corrections are refused, never sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Host: enter the IP address or name of the drive or PLC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: the scale must not be zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>First correction register: the corrections run past address 65535</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Correction: the scale must not be zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Correction: type must be signed (corrections can be negative)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connection closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lost the connection to %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot connect to %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>reading %n register(s) from %1</source>
        <translation>
            <numerusform>reading %n register from %1</numerusform>
            <numerusform>reading %n registers from %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Modbus exception %1 (%2) %3 of %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>invalid reply %1 of %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer from %1 within %2 ms (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 failed: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connected to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connected to %1; registers readable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this output is set up for the dynamic X offset, not per-point corrections</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1 has %2 corrections; this output takes 1 to %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>corrections of part %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1: correction %2 mm is beyond the limit of %3 mm; nothing sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part number %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1: %2 corrections written and verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this output is set up for per-point corrections, not the dynamic X offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X offset %1 mm is beyond the limit of %2 mm; nothing sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X offset %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X offset %1 mm written and verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot send %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot read back %1 from %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read-back mismatch for %1 at register %2: wrote %3, read %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writes verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refused or failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus TCP (Ethernet)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Modbus RTU (serial)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Host</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>IP address or name of the drive or PLC.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>TCP port</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unit id</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The server address of the drive or PLC.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reply timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retries</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: registers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Holding (4x)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Input (3x)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: address</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zero-based protocol address.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: word order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>High word first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Low word first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: scale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>per count</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value = register x scale (in the unit below).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unit %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>writing %n register(s) at %1</source>
        <translation>
            <numerusform>writing %n register at %1</numerusform>
            <numerusform>writing %n registers at %1</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>Notice</name>
    <message>
        <source>Part %1, point %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Starting part %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Continuing run %1 with part %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paused by the operator; the CNC keeps the last correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machining part %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Continuing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The gauge answers again; continuing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measuring the last parts (part %1 next)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waiting for the diameters of part %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The gauge is not ready (%1); part %2 needs the diameters of part %3. Paused, the CNC keeps the last correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No diameters of part %1 for %2 min. Paused, the CNC keeps the last correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run complete: part %1 was the last</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1 finished</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1 measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1 was on the machine when the run was stopped; it is not recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The end of the run could not be stored: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine reported part %1 finished, which the loop did not start; ignored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The history could not be written, part %1 is not stored (%2); the CNC keeps the last correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A reading of %1 mm arrived but no part is waiting to be measured; it was ignored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The diameters of part %1 could not be stored (%2); the CNC keeps the last correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The corrections for part %1 could not be computed (%2); the CNC keeps the last correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1: the controller gave no usable correction at point %2 (x = %3 mm); holding %4 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1: correction at point %2 (x = %3 mm) limited from %4 to %5 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CNC refused the corrections for part %1: %2; it keeps the last correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine did not start part %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not measured: skipped by the operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the reading is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a finite number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>every control point already has a reading; re-take a point to replace it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading %1 mm is more than %2 mm from the nominal %3 mm; check the point (x = %4 mm) and measure again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the point was already measured for part %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1 has not been machined yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1 was not machined under this controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1 is too late: the controller keeps the last %2 parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rejected by the controller: %1 σ from the prediction (gate %2 σ)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rejected by the controller: the deviation %1 mm reaches the alarm band %2 mm; check the part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the controller could not use it: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rejected by the controller: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paused: part %1 is scrap; check the machine, then continue. The CNC keeps the last correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1, point %2 (x = %3 mm): %4 mm is %5 mm above the upper limit %6 mm: rework</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1, point %2 (x = %3 mm): %4 mm is %5 mm below the lower limit %6 mm: scrap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>correlation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>variance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CNC keeps the last correction until the run is restarted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller goes on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The plant no longer matches the controller&apos;s model (part %1, point %2): the %3 test of the innovations over %4 parts is %5, above its limit %6. %7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paused before part %1: the history takes no new part (%2). The run goes on by itself when it does; the CNC keeps the last correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The loop switches to its robust fallback and identifies the plant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From part %1 the loop corrects with its robust fallback (EWMA, weight %2: stable for plant gains 0.5 to 2 times the model&apos;s and one more part of delay) while it identifies the plant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1: the plant cannot be identified yet: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From part %1 the loop corrects with an LQG designed for the plant identified from %2 (plant delay %3 parts, smallest gain margin %4); the mismatch monitor restarts on that model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1: an LQG for the plant identified from %2 (plant delay %3 parts) is proposed; the fallback goes on until an engineer applies it on the Controller page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1: the design for the identified plant is not applied: %2; the fallback goes on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From part %1 the loop corrects with the proposed LQG an engineer applied</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>independence</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller: robust EWMA fallback (weight %1) from part %2, while the plant is identified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller: LQG adapted at part %1 (plant delay %2 parts, smallest gain margin %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller: robust EWMA fallback; a new design waits for an engineer&apos;s Apply (Controller page)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller: robust EWMA fallback; the new design was not applied: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller: LQG applied by an engineer at part %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProbeMandrel</name>
    <message>
        <source>Sample rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The PLC applies the correction every 10 to 100 ms (paper 001).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Silence timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No data for this long: the probe is in error.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Command timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serial RS-232/RS-485</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>probe mandrel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>opening %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>streaming from %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>starting the probe mandrel on %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 on %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProbeStatus</name>
    <message>
        <source>Samples used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frames lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frames duplicated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frames corrupt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Samples dropped (over-range, excitation)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Commands resent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Samples not taken in time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Protocol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (tables up to %2 KiB, CRC-32C)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 (tables up to 64 KiB, CRC-16)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Linearisation table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>version %1, %2, %3 bytes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none (raw ADC codes only)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 / %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>ProcedureWords</name>
    <message>
        <source>The ADC saturated here (raw codes %1 to %2, limits 0 and %3): the point is kept but not used in the fit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point %1: %2 µm at ADC code %3 (mean of %4 samples).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point %1 read again: %2 µm at ADC code %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Typed point %1 added.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point %1 removed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The probe is not ready (%1): type the point instead.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No samples from the probe for %1 s. A mandrel withholds its samples while its ADC is over range (the bar bent beyond the probe&apos;s travel): unload the bar a little. Otherwise check its connection, or type the point.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The load changed while the point was read: capture it again once the bar is still.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Capture stopped; no point added.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the fit needs at least %1 points within the ADC&apos;s range, there are %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the fit needs at least %1 different reference deflections, there are %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the ADC code is %1 at every point: it does not follow the deflection (is the probe connected?)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inside the calibrated range %1 to %2 µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>within the ADC&apos;s range 0 to %1, beyond the calibrated range</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the fitted characteristic is not monotonic: it turns at %1 µm (ADC code %2) %3, so one code would stand for two deflections; check the points near there or choose another degree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the table does not fit the ADC&apos;s range 0 to %1 or 16-bit entries; calibrate over the whole travel of the probe</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the points cannot be fitted (a value that is not a number, or a set-up out of range)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Degree %1, as chosen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Degree %1 chosen by cross-validation: it predicts the points best</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Degree %1 chosen by cross-validation: within one standard error of degree %2, which predicts best, so the simpler curve is kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Degree %1 chosen by cross-validation: within half an ADC code of degree %2, which predicts best, so the simpler curve is kept</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(only degrees up to %1 can be tried with %2 points)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not used in the fit: point(s) %1, where the ADC saturated (a raw code reached 0 or %2). Capture them within the probe&apos;s range, or remove them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check at %1 µm: the ADC saturated (raw code %2 to %3), so the table cannot be verified there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check at %1 µm: the table reads %2 µm, %3 µm off (allowed ±%4 µm).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Passed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Failed: capture more points or choose another degree.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Uploading…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stored; asking the mandrel which table it holds…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verified: the mandrel reports version %1, %2, the same as the image sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The mandrel did not report its table; upload again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload stopped. The saved table is kept; upload it again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload failed: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The saved table is kept; try again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Read-back does not match: the mandrel reports version %1, %2%3; the image has version %4, CRC-32C %5.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, and says the table is not valid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the forward and reverse strokes differ (taper or feed motion, not a dither)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the slide does not move: is the dither running?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>too few samples at constant velocity in each stroke: a longer dither period or faster polling is needed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>too few complete forward and reverse strokes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 N: ΔI = %2 A from %3 stroke pairs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Typed point added.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load %1 removed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The drive read-out is not ready: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No samples from the drive read-out for %1 s: check its connection.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No reliable current difference at %1 N (%2 stroke pairs): %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measurement stopped; no point added.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k_p needs at least %1 known loads, there are %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k_p needs at least 2 different loads</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>load %1 is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the current difference is the same at every load: the drive current is not read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the current difference falls as the load grows (slope %1 N/A): the load acts the other way or the current sign is reversed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check at %1 N: k_p ΔI + offset gives %2 N, %3 N off (allowed ±%4 N).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Failed: measure the loads again.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SerialGauge</name>
    <message>
        <source>Readings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent with the DATA button</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Asked for by TrueTurn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Request string</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sent to ask for a reading, as the interface&apos;s manual gives it; escapes \r \n \xNN.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reply timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Request string: &apos;%1&apos; is empty or has a bad escape (use \r, \n, \xNN)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Serial data cable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>gauge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 open; readings on request</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 open; press DATA on the micrometer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>opening %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer from the gauge on %1 for %2 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Readings accepted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Malformed frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Readings refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bytes discarded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Requests unanswered</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SerialLink</name>
    <message>
        <source>the port went away: cable or adapter unplugged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reading failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>writing failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the %1 on %2 was disconnected (%3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot open %1 for the %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1; reopening (%2)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Simulator</name>
    <message>
        <source>the simulated gauge micrometer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the simulated probe mandrel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the simulated drive-current readout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the simulated CNC output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is unplugged (fault switch)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reconnecting to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>polling the simulated drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer from the simulated drive for %1 polls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>sample refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 A, %2 mm/s, %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Samples refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>simulated gauge ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer from the simulated gauge for %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Readings accepted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Malformed frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Readings refused</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the simulated CNC accepts corrections</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read-back mismatch at value %1: wrote %2 mm, read %3 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not connected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no answer from %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1: the corrections do not match the control points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1: correction %2 mm is beyond the limit of %3 mm; nothing sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1: %2 corrections verified</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>offset %1 mm is beyond the limit of %2 mm; nothing sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X offset %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refused or failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>streaming</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>starting the probe mandrel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameter measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stand-alone: every reading is this diameter (plus noise when switched on).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Resolution, decimals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3 = 0.001 mm, the micrometer of paper 000.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reply timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sample rate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hz</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deflection, plane 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stand-alone: constant bending of the bar.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deflection, plane 2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Silence timeout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Polling period</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Oscillation amplitude</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paper 001: 0.005 to 0.05 mm, inside the tolerance.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Oscillation period</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paper 001: 0.2 to 2 s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Friction current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Correction limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Larger corrections are refused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no data from %1 (silent)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated lathe (built in)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parts of the set-up are turned on the simulated lathe, measured at the control points and the next part is corrected.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>simulated CNC ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>machining</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>waiting for the next part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the simulated gauge does not answer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>automatic measuring is off: diameters are entered by hand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>simulated micrometer ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On a calibration stand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A screw jack bends the bar for the probe linearisation.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A hydraulic jack applies the known loads of the k_p calibration.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::devices::DeviceManager</name>
    <message>
        <source>ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>plugin folder %1 does not exist</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: not a TrueTurn device plugin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: a plugin with id %2 is already loaded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device plugin %1 is not installed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the plugin %1 does not provide a %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no device with id %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (%1 more in error)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 ready; %3 %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n ready</source>
        <translation>
            <numerusform>%n ready</numerusform>
            <numerusform>%n ready</numerusform>
        </translation>
    </message>
    <message>
        <source>device %1: the saved entry is incomplete</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::reports::ReportCharts</name>
    <message>
        <source>Individual diameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subgroup means</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part in order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>subgroup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diameter, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diameter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mean</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centre line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>control limits</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rule violations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>end of the baseline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subgroup ranges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subgroup standard deviations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moving ranges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spread, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Distribution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fitted normal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nominal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x along the shaft, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tolerance band</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Capability</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no tolerance stored</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cpk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cpm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pp</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ppk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Method</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>normal distribution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>percentiles (ISO 22514-2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normality p (AD)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>σ within, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>σ overall, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mean, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tolerance, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point %1 at x = %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%1 chart, limits from %n parts</source>
        <translation type="unfinished">
            <numerusform>%1 chart, limits from %n part</numerusform>
            <numerusform>%1 chart, limits from %n parts</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%1 chart of subgroups of %2, limits from %n subgroups</source>
        <translation type="unfinished">
            <numerusform>%1 chart of subgroups of %2, limits from %n subgroup</numerusform>
            <numerusform>%1 chart of subgroups of %2, limits from %n subgroups</numerusform>
        </translation>
    </message>
    <message>
        <source>good %1 · rework %2 · scrap %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>… and %n more</source>
        <translation type="unfinished">
            <numerusform>… and %n more</numerusform>
            <numerusform>… and %n more</numerusform>
        </translation>
    </message>
    <message>
        <source>%1: parts %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>controller changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EWMA fallback (weight %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>proposed LQG applied%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LQG refined%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LQG adapted%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1, part %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, delay z = %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::reports::ReportPdf</name>
    <message>
        <source>Quality report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Job: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Runs: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parts stored: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n parts, %1</source>
        <translation type="unfinished">
            <numerusform>%n part, %1</numerusform>
            <numerusform>%n parts, %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Printed %1 UTC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point · x, mm · n · mean, mm · Cpk · Ppk · rule violations · good / rework / scrap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Checked by: ______________________   Date: ____________   Signature: ______________________</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>machine %1, job %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Rule violations (Western Electric): %n</source>
        <translation type="unfinished">
            <numerusform>Rule violations (Western Electric): %n</numerusform>
            <numerusform>Rule violations (Western Electric): %n</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>Controller changes of the adaptive loop (marked on the chart): %n</source>
        <translation>
            <numerusform>Controller changes of the adaptive loop (marked on the chart): %n</numerusform>
            <numerusform>Controller changes of the adaptive loop (marked on the chart): %n</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tt::runtime::BoringTargets</name>
    <message>
        <source>Station&apos;s PLC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The simulated pass cannot begin: its scenario or its mandrel&apos;s calibration is refused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The chosen CNC output is gone.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No devices are configured.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::runtime::DeviceHost</name>
    <message>
        <source>TrueTurn is closing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the device plugin %1 is not installed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this source runs no boring pass of its own</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the CNC output is no longer on the Devices page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this instrument is not on a calibration stand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this stand has no screw jack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this stand has no hydraulic jack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>this probe cannot take a table upload</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::runtime::DeviceHub</name>
    <message>
        <source>ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (%1 more in error)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 ready; %3 %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n ready</source>
        <translation type="unfinished">
            <numerusform>%n ready</numerusform>
            <numerusform>%n ready</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tt::runtime::LatheLink</name>
    <message>
        <source>the %1 “%2” is no longer on the Devices page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Run page was closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a new run was started</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>gauge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CNC output</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::runtime::LoopWorker</name>
    <message>
        <source>A run is already going; stop it first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The run history cannot be opened: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The run cannot start: the CNC output “%1” writes programs for a diameter of %2 mm, the set-up %3 turns %4 mm; correct the nominal diameter on the Devices page or choose another set-up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The run cannot start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n gauge reading(s) taken while the diameters were typed by hand were not used.</source>
        <translation type="unfinished">
            <numerusform>%n gauge reading taken while the diameters were typed by hand was not used.</numerusform>
            <numerusform>%n gauge readings taken while the diameters were typed by hand were not used.</numerusform>
        </translation>
    </message>
    <message>
        <source>No run is going: the diameters were not taken.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1 is not the part waiting for its diameters; nothing was taken.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No part is on the machine.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The new controller tuning was not taken: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::runtime::MachineCatalog</name>
    <message>
        <source>Real lathe (Devices page)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>each part&apos;s corrections go to the CNC; you machine the part and press Part finished.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>still connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No CNC output is chosen. Add a G-code file or Modbus correction output on the Devices page and choose it under CNC output.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CNC output chosen is no longer on the Devices page; choose another.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CNC output “%1” is %2: %3. Check it on the Devices page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The gauge chosen is no longer on the Devices page; choose another or type the diameters by hand.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The gauge “%1” is %2: %3. Check it on the Devices page, or choose to type the diameters by hand.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::runtime::TerminalDevices</name>
    <message>
        <source>Simulated gauge micrometer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated probe mandrel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated drive-current readout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated CNC output</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui</name>
    <message>
        <source>Plant database offline since %1; parts kept on this terminal: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plant database: connecting; parts kept on this terminal: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plant database: every part sent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plant database: sending; parts kept on this terminal: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1. The journal on this terminal is full (%2 of %3 MiB): the loop takes no new part until the plant database has taken parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1. The journal on this terminal is nearly full (%2 of %3 MiB)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::About</name>
    <message>
        <source>In-process compensation of boring-bar deflection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed scheduling against force deformation, with G-code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Neural corrective pulse of the feed drives at corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hydraulic feed stabilisation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibration of the probe and the gauge, tool stiffness table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The Reports page and PDF reports</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h2&gt;TrueTurn %1&lt;/h2&gt;&lt;p&gt;Adaptive accuracy control for lathes.&lt;/p&gt;&lt;p&gt;&lt;b&gt;Implemented:&lt;/b&gt;&lt;/p&gt;%2&lt;p&gt;&lt;b&gt;Not yet implemented:&lt;/b&gt;&lt;/p&gt;%3&lt;p&gt;Qt %4&lt;/p&gt;&lt;p&gt;Log file: %5&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not written</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run-to-run LQG control of the shaft profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices: gauge, probe mandrel, Modbus, CNC correction output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run history (SQLite, PostgreSQL), SPC figures (report command)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The Controller page: tuning with live predictions and margins</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Integral action, double EWMA and model-mismatch detection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ARMA identification of the disturbance from the history</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Users, roles, log-in and the audit trail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kiosk mode and an on-screen keypad</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>One run request for the Run page, CLI and resume</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Devices in a thread of their own</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The LinuxCNC lathe on the Run page and in simulate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plant-wide history: a journal on each terminal, the Plant page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retraining of the corrective pulse on drive drifts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Adaptive control: a robust fallback and a new design on a mismatch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The controller&apos;s changes on the Reports page&apos;s control chart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Adapting to the tool&apos;s wear and the lathe&apos;s warm-up</source>
        <translation type="unfinished"></translation>
    </message>
</context>
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
    <name>tt::ui::AuditDialog</name>
    <message>
        <source>Setting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Log-in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Audit trail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Filter: name, tool, field or value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>When</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Who</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Role</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subject</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Field</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Old value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The database cannot be opened: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not shown: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n record(s)</source>
        <translation>
            <numerusform>%n record</numerusform>
            <numerusform>%n records</numerusform>
        </translation>
    </message>
    <message>
        <source>Export the audit trail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not written: %1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n record(s) written to %1</source>
        <translation>
            <numerusform>%n record written to %1</numerusform>
            <numerusform>%n records written to %1</numerusform>
        </translation>
    </message>
    <message>
        <source>logged in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>password set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PIN set</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unlocked</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>user %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Hash chain intact: %n row(s) checked.</source>
        <translation>
            <numerusform>Hash chain intact: %n row checked.</numerusform>
            <numerusform>Hash chain intact: %n rows checked.</numerusform>
        </translation>
    </message>
    <message>
        <source>row %1 edited</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>row %1 inserted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the chain&apos;s head does not match its last row</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n row(s) deleted before row %1</source>
        <translation>
            <numerusform>%n row deleted before row %1</numerusform>
            <numerusform>%n rows deleted before row %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n row(s) deleted at the end</source>
        <translation>
            <numerusform>%n row deleted at the end</numerusform>
            <numerusform>%n rows deleted at the end</numerusform>
        </translation>
    </message>
    <message>
        <source>Hash chain BROKEN: the trail was changed outside TrueTurn (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hash chain not checked: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::BoringPanel</name>
    <message>
        <source>The devices were changed, so the compensation stopped. The CNC keeps the offset it holds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The chosen source device is gone.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No CNC output for the dynamic X offset: add one on the Devices page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose where the deflection comes from.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No tool: add the boring bar to the tool table on the Tools page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the tool.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Starting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zero the offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CNC holds a dynamic X offset of %1 mm. Set it to 0 now? The tool moves by %2 mm: do this only with the tool out of the bore.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The CNC did not take the offset 0: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The bore is finished: largest diameter error %1 mm with compensation, %2 mm without (%3 %).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Holding</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deflection %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deflection —</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force %1 N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force —</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped. The CNC keeps the offset it holds. Choose the source, the tool and the limits, then Start.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bore diameter error from %1 mm in: %2 mm with compensation, %3 mm without</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bore diameter error: shown from %1 mm into the bore</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool at %1 of %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset applied</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Without compensation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>With compensation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set-up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plane along X</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CNC output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Offset limit ±</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rate limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PLC cycle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cutting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulate a silent read-out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zero the offset…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plane 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plane 2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Taper</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Contour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: probe mandrel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: current + dither</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Station: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (measured)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not calibrated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The tool table cannot be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No tool in the tool table (Tools page).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deflection and dynamic X offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time, s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bore diameter error along the bore (simulated station)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position in the bore, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameter error, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k %1 N/mm%2 · k_p %3 N/A
L/d %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Real (simulator)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>boring bar: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::CalibrationPage</name>
    <message>
        <source>The devices changed while a calibration was open, so it was closed; the captured points are kept. Open it again to continue.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start over</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forget the %1 captured points of the unfinished calibration?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not uploaded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>verified, CRC %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>read-back CRC %1 does not match</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Probe mandrel linearisation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Builds the table ADC code → deflection that the mandrel&apos;s microcontroller uses: capture points against a dial indicator, fit the sensor&apos;s characteristic, save a new table version and upload it with read-back of its CRC.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Continue the calibration (%1 points kept)…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Linearise a probe mandrel…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Probe</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Version</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>By</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Degree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Table error, µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In the mandrel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current-to-force gain k_p</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Known loads on the cross slide against the motor current difference with dither; the result is written into the tool table.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Calibrate k_p from known loads…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>When</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k_p, N/A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>R²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The calibration database cannot be opened: %1. Tables can still be built and exported, not saved.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::CalibrationWizard</name>
    <message>
        <source>&lt; Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next &gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Finish</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ControllerPage</name>
    <message>
        <source>Controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delay z, parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Max step per part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dead band (EWMA)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Filter (z + b)/(z − a)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>R1 (error)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>R2 (correction)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k_eff LQG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k_eff EWMA</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gain marg.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delay, parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Disk α</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Revert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step at point 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part after the step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error / step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>|S| at point 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>frequency, rad per part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>|S|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The design is refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re-synthesis %1 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning: a plant one part slower than the model destabilises this design (delay margin under one part). Best EWMA weight %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The design tolerates one more part of delay. Best EWMA weight %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EWMA</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LQG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply the new controller tuning from the next part?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Warning: its delay margin is under one part: a plant one part slower than the model destabilises it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply tuning</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> mm²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delay margin in parts (phase margin / crossover) / whole extra parts of delay the loop stays stable with</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied to the running loop: the new tuning takes over at the next part, without a jump in the correction.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied: no run is going; the next Start on the Run page uses this tuning.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Integral action</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Adds an integrating disturbance state to the LQG design: a step (tool change, new blanks) is corrected completely, at some cost in k_eff</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>weight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identify from history</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Newest run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n parts, started %1</source>
        <translation>
            <numerusform>%n part, started %1</numerusform>
            <numerusform>%n parts, started %1</numerusform>
        </translation>
    </message>
    <message>
        <source>Identification failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Phase margin %1, sensitivity peak |S| %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identifies the plant of a stored run at every point (gain, plant delay, disturbance as ARMA(p, q) with standard errors) and designs the controller for it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identified model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Design on the identified model (per point gain and disturbance, the plant delay) instead of the typed filter</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use the loop&apos;s proposal (part %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The adaptive loop identified the plant and proposes a design for it; take it into the page, check the predictions and apply it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identifying the plant of the stored run…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point %1: gain %2 ± %3, ARMA(%4, %5) AR [%6] MA [%7], σ² %8 mm², Ljung–Box p %9</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the design&apos;s margins hold (gain margin %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the design fails its margins: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1, parts %2 .. %3: plant delay %4 parts; point 1 gain %5 ± %6 (every point in the tooltip); %7</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point %1: gain %2 ± %3, σ² %4 mm²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The loop&apos;s proposal of part %1: plant delay %2 parts, identified from %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The proposal cannot be used: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::CornerMoveEditor</name>
    <message>
        <source>Corner between two moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X after</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z after</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> rad/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pulse on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X, cross slide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Z, carriage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pulse length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speeds as entered</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: X %2 → %3, Z %4 → %5</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::CornerTool</name>
    <message>
        <source>Corner pulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paths</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drift monitor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom on the corner</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Training moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Train network</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retrain now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing running.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The corner preset cannot be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error %1 → %2 µm, −%3 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Network&apos;s pulse %1 V</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Best pulse %1 V; no network for this pulse yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Network trained.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run finished.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Finding the best pulse of training move %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Training the network: epoch %1 of at most %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running corner %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retraining the network: epoch %1 of at most %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled: the network of before is kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No network yet. Training finds the best pulse of each training move on the simulator (a bracketed search of U = k1·e_max + k2·e_mean), then the 4-10-1 network learns it from the four motor speeds.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Network 4-%1-1 for a %2 ms pulse on %3: %4 epochs (best %5), RMS amplitude error %6 mV on the training moves, %7 mV on the validation moves. The best pulses cut the training moves&apos; error by %8 %.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Retrained %n time(s) since.</source>
        <translation>
            <numerusform>Retrained %n time since.</numerusform>
            <numerusform>Retrained %n times since.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n corner(s): mean error %1 → %2 µm (−%3 %).</source>
        <translation>
            <numerusform>%n corner: mean error %1 → %2 µm (−%3 %).</numerusform>
            <numerusform>%n corners: mean error %1 → %2 µm (−%3 %).</numerusform>
        </translation>
    </message>
    <message>
        <source>No retraining was needed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>After it: −%1 %.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drift</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Friction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity gain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Inertia</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Retrained on demand on %n corner(s); identified %1.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Retraining on demand refused: %1. The network in use is kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Identifying the drives from the recorded corners</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Finding the best pulse of move %1 of %2 on the identified drives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X: friction × %1, inertia × %2, gain × %3; Z: friction × %4, inertia × %5, gain × %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured cost %1 % off the prediction after corner %2; identified %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Retrained: validation cost %1 → %2 µm.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The retrained network was refused (%1); the network in use is kept.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Runs corners with the network&apos;s pulse on the simulated machine; from the middle corner on, the chosen property of the chosen drive is multiplied by the factor. After each corner the monitor compares the measured cost with the predicted one over the last %1 corners (misses removed) and retrains above %2 %; a retrained network is taken only when it does better on held-out moves.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n more retraining(s) later.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Last difference of the monitor: %1 % (threshold %2 %).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On the drives as identified after the drift.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paper&apos;s drives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Soft drives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paper&apos;s drives: the 1V340F30 lathe of paper 002 (Kv 16.7 1/s), where drifts of the inertia hardly move the best pulse. Soft drives: the same lathe with half the position loop gain (Kv 8.35 1/s) and a slow cross slide (50 ms), where they do.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::DeformationModelPanel</name>
    <message>
        <source>Terms of the next fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cubic in z (a, f quadratic)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>full quadratic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>linear with interactions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>linear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove insignificant terms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Term (coded)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Coefficient, µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Std. error, µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t-value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No model yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>significant at 95 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>NOT significant at 95 %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;%1 points, %2 terms.&lt;/b&gt; R² %3, adjusted R² %4. F %5 against the table value F(0.95; %6, %7) = %8: %9. Residual 2σ %10 µm. t-values below %11 are not significant.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Removed as insignificant: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::DevicesPage</name>
    <message>
        <source>%1 — %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New: %1
(not added yet)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings to correct: %1 (marked in red).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove %1? Its settings are deleted; the loop can no longer use it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not tested: correct the settings marked in red first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Testing the connection…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No connection: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connected — %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No answer within %1 s: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not added</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fill in the settings, test the connection, then add the device.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (last value)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Device instances</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a device of type</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No device selected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a gauge micrometer, probe mandrel, drive-current readout or correction output to the CNC. The built-in simulator provides every kind, with fault switches.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Settings</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Test connection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add device</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Revert</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulator fault switches</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Silent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Noisy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stuck value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Malformed frames</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unplugged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Counters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not tested: a run is going on the Run page and would take the test reading as a diameter. Stop the run first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not tested: a run is going on the Run page and these settings would close the device it uses. Stop the run first, or test with the applied settings.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>changed settings of a device on the Devices page</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::FeedChartTabs</name>
    <message>
        <source>Feed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spool and magnet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweep</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweep table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time, s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed, mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slot opening, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>magnet current, mA</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed after the load step, with and without the regulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slot opening</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Magnet current</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>set feed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>without regulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>with regulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed after the load step for each ξ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed after the load step for each gain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ξ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>gain K_a</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>feed,
mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>settling,
s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>overshoot,
%</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spool
overshoot, %</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>regulates</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no: runs away</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slot fully open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>yes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>gain ×
K_p</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no: unstable</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::FeedParameterForm</name>
    <message>
        <source>Sensor: the tool&apos;s elastic displacement</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Amplifier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Electromagnet and armature</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spool of the flow regulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slot of the flow regulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cylinder and carriage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Signal per newton</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mV/N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed exponent y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gain K_a</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>V/V</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bias U₀</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>V</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Coil turns</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gap permeance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>µH</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gap section</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Coil circuit r</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ω</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time constant T_z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Damping ratio ξ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gain K_z</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>µm/N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discharge coeff. μ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plunger d₁</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pressure drop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>MPa</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Oil density</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>kg/m³</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Full opening</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Carriage mass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>kg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Piston D</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Leakage k_y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm³/(s·Pa)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set feed S</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mm/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 .. %2 %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Design gain for the load</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The radial force follows the chip: P_y = P (v/S)^y; y = 0 is the paper&apos;s constant force.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bias current %1 mA; the lap that keeps the slot shut at the bias: %2 mm.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>L = %1 H, T_k = %2 ms, K_e = %3 N/A²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ξ &lt; 1: the spool oscillates (the paper recommends ξ slightly above 1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ξ ≥ 1: aperiodic, settles in about 3T.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k_s = %1 m²/s; full flow %2 cm³/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F = %1 cm², k₀ = %2 m⁻², T_c = %3 ms, pump %4 cm³/s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::FeedScheduleTool</name>
    <message>
        <source>Feed schedule</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The built-in set-up cannot be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Experiments on the simulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Experiment to fit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fitting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model files (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be used: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machining on the simulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deformation Y; the tool travels z %1 → %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 mm/rev</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Yc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scheduled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>scheduled feed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fmin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fmax</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the CNC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CNC programs (*.nc *.txt)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be written: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The program was written to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No model yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated experiments (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 points, %3 terms. R² %4, F %5 (table %6), 2σ %7 µm.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Y1 %1 µm
quality</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Y2 %1 µm
output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>– µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Y1
quality</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Y2
output</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>&lt;b&gt;%n segment(s)&lt;/b&gt;, feeds %1 → %2 mm/rev.</source>
        <translation>
            <numerusform>&lt;b&gt;%n segment&lt;/b&gt;, feeds %1 → %2 mm/rev.</numerusform>
            <numerusform>&lt;b&gt;%n segments&lt;/b&gt;, feeds %1 → %2 mm/rev.</numerusform>
        </translation>
    </message>
    <message>
        <source>Time %1 min against %2 min at fmin: &lt;b&gt;%3 % saved&lt;/b&gt; (fmax %4 min).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The model names no machine job (spindle speed): no times, no program.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulator: within &lt;b&gt;%1 %&lt;/b&gt; of Yc (worst at z %2 mm); constant fmax exceeds Yc by %3 %.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No simulator for this model&apos;s set-up: the check is not available.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force-deformation model Y(a, f, z)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run the experiments on the simulator and fit the model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load a model file written by &apos;trueturn fit-deformation --json&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Depth of cut a</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feeds, mm/rev</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pass z, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Shortest segment</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CNC dialect</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fanuc-style</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LinuxCNC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check on simulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save program…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Level Yc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>z, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Y, µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>f, mm/rev</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Curves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CNC program</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Model statistics</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refining the model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refining: round %1, bar %2 of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refined at a = %1 mm (%2, test bars added: %3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Refined in %n round(s): test bars %1, gauge points %2; before, the pass was %3 % off Yc.</source>
        <translation>
            <numerusform>Refined in %n round: test bars %1, gauge points %2; before, the pass was %3 % off Yc.</numerusform>
            <numerusform>Refined in %n rounds: test bars %1, gauge points %2; before, the pass was %3 % off Yc.</numerusform>
        </translation>
    </message>
    <message>
        <source>The feed step alone leaves the band: try the centred switch.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulator: &lt;b&gt;%1 %&lt;/b&gt; off Yc at z %2 mm, outside ±10 %.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refine runs a targeted experiment at this depth, refits the model and checks again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine targeted bars on the simulator, refit the model at this depth and check again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Where a feed step switches to the next: where the next feed reaches Yc (the paper), or where the two feeds&apos; mean is Yc (half the deviation)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at Yc (paper)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centred on Yc</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed step, mm/rev</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::FirstStartDialog</name>
    <message>
        <source>First start: create the administrator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Create the administrator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No user exists yet. The administrator adds the operators, engineers and quality staff and sets what they may change. The password needs at least %1 characters.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Repeat the password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Create and log in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The two passwords differ; type them again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not created: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::HistoryCheck</name>
    <message>
        <source>not available — %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run history</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The run history cannot be used: %1

Runs are not recorded until this is fixed (Settings shows where the history is kept).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::HydraulicFeedTool</name>
    <message>
        <source>Hydraulic feed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sensor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Amplifier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Electromagnet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cylinder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>load P: leakage α₀ = k_y P/F</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>chip thickness: P_y = P (v/S)^%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no loop: the force does not follow the feed (y = 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>at</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Preset values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweep ξ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweep gain</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The load step at %1 s comes after the end of the simulation (%2 s).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A gain sweep needs a load: the gains are multiples of the one that makes up its leakage.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulating with and without the regulator…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweeping ξ…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sweeping the gain…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled; the curves shown are from the last finished run.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n run(s) swept; settling times and overshoots are on the Sweep table tab.</source>
        <translation>
            <numerusform>%n run swept; settling times and overshoots are on the Sweep table tab.</numerusform>
            <numerusform>%n runs swept; settling times and overshoots are on the Sweep table tab.</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>The spool swings past its final opening in %n of them.</source>
        <translation>
            <numerusform>The spool swings past its final opening in %n of them.</numerusform>
            <numerusform>The spool swings past its final opening in %n of them.</numerusform>
        </translation>
    </message>
    <message>
        <source>Set a load first: the gain is designed to make up its leakage.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gain %1 V/V and lap %2 mm: the slot opens by just the leakage of %3 N at the set feed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a block on the diagram to edit its parameters, then Simulate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stability boundary: K_a = %1 (%2 × the design gain %3); simulated at ±5 %: %4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>confirmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not confirmed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No gain destabilises the chain; the slot opens fully above K_a = %1 (%2 × the design gain %3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No gain up to 1e5 destabilises the chain (design gain %1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export the chart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chart written to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export the curves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Curves written to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n run(s) beyond the stability boundary.</source>
        <translation>
            <numerusform>%n run beyond the stability boundary.</numerusform>
            <numerusform>%n runs beyond the stability boundary.</numerusform>
        </translation>
    </message>
    <message>
        <source>Regulator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feedback of the feed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed-forward of the force (paper)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the feedback</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the feed-forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Steady feed %1 mm/s with %7, %2 mm/s without (set %3). Settling (5 %): %4 s with, %5 s without; overshoot %6 %.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2 dB) at %3 rad/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1° at %2 rad/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Margins of the feedback loop: gain %1, phase %2; closed loop %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>UNSTABLE</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The carriage stalled from %1 s to %2 s: the flow cannot make up the load&apos;s leakage.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The slot was fully open from %1 s to %2 s: the regulator could give no more flow.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The feedback asked for less than a shut slot from %1 s to %2 s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The feed ends %1 % off the set feed (band ±%2 %).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Without the regulator the carriage stalls: the pump&apos;s flow cannot make up the leakage.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::InterruptedRun</name>
    <message>
        <source>no end</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1 (%2, %3, %4 of %5 parts done) was interrupted. Continue it from part %6?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Interrupted run</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::Kiosk</name>
    <message>
        <source>Quit the terminal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This terminal runs in kiosk mode: only an engineer may quit it.

Are you an engineer, and do you want to quit TrueTurn?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::KpCalibrationWizard</name>
    <message>
        <source>k_p from known loads</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::KpFitPage</name>
    <message>
        <source>Refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>known loads</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k_p ΔI + offset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>residual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load against ΔI</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ΔI, A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load, N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Residuals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load − fit, N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not accepted: a verification load failed or is being measured. Measure it again, or go back to the loads.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check load</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measuring the verification load…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;k_p = %1 N/A&lt;/b&gt; (offset %2 N, R² %3, residual RMS %4 N) from %5 loads.&lt;/p&gt;&lt;p&gt;The straight line P = k_p ΔI + offset is fitted by least squares; the offset should be small against the loads (it shows an asymmetry of the drive). Check it at a load not used in the fit before going on.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit and verify k_p</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force against the current difference, then a verification load not used in the fit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verification load</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> N</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::KpLoadsPage</name>
    <message>
        <source>measured, %1 pairs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>typed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>known loads</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Known loads</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply the load, enter what the gauge shows, measure. At least 3 loads, 0 included.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Known load</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ΔI (typed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add typed point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load, N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ΔI, A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Current difference against the load</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> N</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No drive read-out: type the current differences</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive read-out: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live ΔI %1 A (last stroke pair)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waiting for dither strokes…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measuring at %1 N: keep the load steady while it settles…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measuring at %1 N: %2 stroke pairs averaged…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The stand&apos;s hydraulic jack applies the load you enter. Measure at least 3 loads, 0 included.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Repeat load</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::KpSavePage</name>
    <message>
        <source>Save k_p</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter your name on the Settings page first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not saved: no operator name (Settings).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The calibration database is not open.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved. No tool was chosen, so the tool table is unchanged.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved; k_p %1 N/A written into %2 (recorded in the tool audit).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The calibration is kept with your name; the chosen tools get the new k_p.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save and write into the tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k_p = %1 N/A, to be written into: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no tool (only the calibration is kept)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::KpSetupPage</name>
    <message>
        <source>%1 %2 — k_p now %3 N/A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drive and tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k_p turns the cross-feed motor current into force: P = k_p (I_fwd − I_rev) / 2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cross-feed drive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the new k_p into</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Put a dynamometer or a hydraulic jack with a gauge between the tool block and the workpiece so it pushes the tool towards the axis like the cutting force. Start the cross-feed dither (as for boring) and keep it running; at each load the current is averaged at constant velocity in both directions.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::LathePanel</name>
    <message>
        <source>No run on the lathe</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No part on the machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine part %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Press Start: the corrections of part 1 go to the CNC.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The next part starts when its corrections are on the CNC.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its corrections are on the CNC.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its corrections are on the CNC (%1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to measure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1: type its diameters below</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measure part %1 at x = %2 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point %1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 · last reading %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take gauge reading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1 finished</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part finished</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::LoginDialog</name>
    <message>
        <source>Log in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Log in to TrueTurn</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Password or PIN</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>User</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Wrong name or password. %n attempt(s) left before the lock-out.</source>
        <translation>
            <numerusform>Wrong name or password. %n attempt left before the lock-out.</numerusform>
            <numerusform>Wrong name or password. %n attempts left before the lock-out.</numerusform>
        </translation>
    </message>
    <message>
        <source>Too many failed log-ins: %1 is locked until %2. An administrator can unlock it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot log in: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
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
    <message>
        <source>a run is going (loop: %1); quitting stops it, its finished parts stay in the history</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 not applied; quitting discards them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quit TrueTurn?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Before you quit:
• %1

Quit anyway?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>On-screen &amp;keypad</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Sound on rework or scrap</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ManualEntryPanel</name>
    <message>
        <source>Part %1 by hand: diameters in mm, nominal %2, Enter for the next point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>By hand: no part is waiting for its diameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x = %1 mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&apos;%1&apos; is not a diameter in mm.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rejected: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No part is waiting for its diameters: nothing was sent.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::MaterialsModel</name>
    <message>
        <source>Material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Young&apos;s modulus E, MPa</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>material: the name must not be empty</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Young&apos;s modulus E: &apos;%1&apos; must be a number between %2 and %3 MPa</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::MeasurementsModel</name>
    <message>
        <source>—</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>accepted</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rejected</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nominal, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Deviation, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verdict</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reason</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Correction, mm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::MeasurementsPage</name>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Only rejected and unmeasured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The run history cannot be read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No parts recorded yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start a run on the Run page: every measured part appears here with its diameters at the control points, whether each was accepted and why not.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run %1 · %2 · %3, z = %4 · %5 parts · %6</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 parts recorded, %2 measured; %3 values rejected or not measured.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LQG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EWMA</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>open loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>complete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not finished</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::NumericKeypad</name>
    <message>
        <source>Enter a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>OK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Limits: %1 … %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type a number first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is outside the limits (%2).</source>
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
        <source>Gauge micrometer, probe mandrel, drive-current readout and the correction output to the CNC; the built-in simulator is always available.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Process</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plant</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::PlantModel</name>
    <message>
        <source>running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>offline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>offline, last part %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>idle</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>idle, last part %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cpk of the last %1 parts; %2 parts before: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Kept on
terminal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Today
good / rework / scrap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cpk
point %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::PlantPage</name>
    <message>
        <source>Refresh</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click a machine to open its reports. Cpk of the last %1 parts per control point, ▲▼ its change against the %1 before; the page reads the plant database every %2 s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plant database: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No machine has written to the plant database yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every terminal that stores its runs here appears with its state, the parts it still keeps, today&apos;s verdicts, the capability of its last parts and its open alarms.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the plant database…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot read the plant database: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Read at %1: %n machine(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeAcceptPage</name>
    <message>
        <source>(typed points)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;Characteristic of degree %1 from %2 points, residual RMS %3 µm.&lt;/p&gt;&lt;p&gt;Table: %4 entries of %5 nm, worst error at the calibration points %6 µm, step between codes up to %7 µm; %8 entries outside the calibrated range %9 .. %10 µm are extrapolated.%11&lt;/p&gt;&lt;p&gt;It will be saved as version &lt;b&gt;%12&lt;/b&gt; of %13, plane %14, by &lt;b&gt;%15&lt;/b&gt;.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(no operator name — set it in Settings)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>I accept this linearisation table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold still, then the live codes are averaged…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not accepted: a verification point failed or is being read. Check again, or go back and capture more points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 % of the table lies outside the calibrated range and is extrapolated; calibrate over more of the probe&apos;s travel.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no verification point yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 verification points passed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verify the table — %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Verify and accept the table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load the bar to a deflection not captured and check that the table reads it; the table is stored only when you accept it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stand&apos;s screw jack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bend the bar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference reading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> µm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeCalibrationWizard</name>
    <message>
        <source>Probe mandrel linearisation</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeCapturePage</name>
    <message>
        <source>Probe: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live ADC code %1 (mean of %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waiting for probe samples…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>live, %1 samples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>typed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>captured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Capture points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bend the bar</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference reading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Capture point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ADC code (typed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add typed point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference, µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ADC code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Source</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ADC code against the reference deflection</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference deflection, µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Captured points stay here when you go back or cancel.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No probe: type the points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Live ADC code %1 (mean of %2) — at the ADC&apos;s limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Hold still: the bar settles…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Averaging the live codes at %1 µm…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The jack bends the bar by at most ±2000 µm.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The jack bends the bar to %1 µm; capture when the live code is steady.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No probe mandrel to read: type the point instead.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The typed code is outside the ADC&apos;s range.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — ADC saturated (%2 to %3 of 0 to %4), not used</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ADC saturated</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Load the bar, read the instrument, capture: the bar holds still, then the codes are averaged. At least %1 points; both directions.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stand&apos;s screw jack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Repeat point</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeChoosePage</name>
    <message>
        <source>No probe mandrel is configured: add one on the Devices page, or type the points.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is ready.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2 — you can still type the points by hand.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Probe and bending plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Which probe mandrel is calibrated, in which plane, and its ADC resolution.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Probe mandrel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bending plane</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ADC resolution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X — radial (bore diameter)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Y — tangential</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> bit</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeFitPage</name>
    <message>
        <source>degree %1: leave-one-out %2 µm, in-sample %3 µm%4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> — chosen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Refused: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#1b5e20&apos;&gt;&lt;b&gt;Monotonic over the whole ADC range; residual RMS %1 µm.&lt;/b&gt;&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>captured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fitted, degree %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>residual</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>zero</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit the characteristic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The inductive sensor&apos;s characteristic is a polynomial of degree 2 to 4; the table inverts it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Degree</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Automatic (cross-validation)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Characteristic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference deflection, µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ADC code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Residuals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Table reading − reference, µm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Each point is predicted from a fit to the others (leave-one-out); a higher degree always fits the points themselves better, so it is kept only when it predicts them better.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeReferencePage</name>
    <message>
        <source>Set up the reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The deflection is read on an instrument at the tool tip while the bar is loaded.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference instrument</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dial indicator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Micrometer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Division of the instrument</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1. Clamp the boring bar as for cutting; mount the instrument on the lathe bed touching the tool tip in the chosen plane.
2. With the bar unloaded, set the instrument to zero.
3. Load the bar in both directions in steps (a screw jack against the tool block) over the whole travel of the probe; at each step read the instrument and capture the point. Aim for 15 to 25 points, both signs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> µm</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ProbeSavePage</name>
    <message>
        <source>Export the table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C header (*.h);;Binary image (*.bin);;CSV (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The calibration database is not open; export the table instead.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter your name on the Settings page first: the table is saved with it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not saved: no operator name (Settings).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(typed points)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved as version %1 of %2 by %3 at %4.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Now upload it to the mandrel.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported to %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save and upload</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The table is saved as a new version with your name, then sent to the mandrel and read back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the table, then upload it to %1. Finish is possible once the mandrel reports the same version and CRC as the image sent.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This probe takes no uploads here: save the table and export it for the microcontroller (C header or binary image).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Upload to the mandrel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ProcessPage</name>
    <message>
        <source>Process design</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Feed scheduling against force deformation with its CNC program, the corrective pulse of the feed drives at corners, and hydraulic feed stabilisation.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ProfilePanel</name>
    <message>
        <source>Last part: diameter error along the shaft</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x along the shaft, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>diameter error, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error at the points, last %1 parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tolerance ±%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>model d(x)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>correction, part %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>part %1 gauged</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>between points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x = %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>tolerance</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>true profile</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ReportFilterBar</name>
    <message>
        <source>all machines</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all runs</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Run %1 · %2 · %n parts</source>
        <translation>
            <numerusform>Run %1 · %2 · %n part</numerusform>
            <numerusform>Run %1 · %2 · %n parts</numerusform>
        </translation>
    </message>
    <message>
        <source>Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>From</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>To</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Subgroup, parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Limits from first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>any date</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>by subgroup size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X̄-R</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>X̄-s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>I-MR</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ReportViews</name>
    <message numerus="yes">
        <source>Rule violations (Western Electric): %n</source>
        <translation>
            <numerusform>Rule violations (Western Electric): %n</numerusform>
            <numerusform>Rule violations (Western Electric): %n</numerusform>
        </translation>
    </message>
    <message>
        <source>run %1, part %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Profile of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Control chart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Distribution and capability</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part profile</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All points</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part in order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Index</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>95 % interval</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Controller changes (marked): %n</source>
        <translation>
            <numerusform>Controller changes (marked): %n</numerusform>
            <numerusform>Controller changes (marked): %n</numerusform>
        </translation>
    </message>
    <message>
        <source>The controller changes of these runs could not be read: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ReportsPage</name>
    <message>
        <source>Analyse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DFQ…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No measured parts for this choice</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Every part measured on the Run page is stored with its diameters and verdicts. Choose the machine, run and dates, then Analyse: control charts, capability and exports.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reading the history…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Written: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No measured parts for this choice.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n readings</source>
        <translation>
            <numerusform>%n reading</numerusform>
            <numerusform>%n readings</numerusform>
        </translation>
    </message>
    <message>
        <source>Save the PDF report</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the readings as CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the readings as DFQ</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>AQDEF files (*.dfq)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing the PDF…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing the DFQ file…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Writing the CSV file…</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::RunPage</name>
    <message>
        <source>Shaft profile (run-to-run)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Boring bar (in-process)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::SettingsForm</name>
    <message>
        <source>%1 to %2</source>
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
    <message>
        <source>Users and audit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Logged in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Log out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Users…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Audit trail…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This lathe in the plant database</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ShaftRunPanel</name>
    <message>
        <source>Pause on scrap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ready</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>connecting</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not answering</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the Run page was closed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set-up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Controller</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delay z, parts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>LQG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>EWMA</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open loop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>×1 (6 min a part)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>×60 (6 s a part)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>×360 (1 s a part)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>×3600 (fastest)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CNC output</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameters from</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Typed in by hand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameters by hand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part not measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Alarms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not started: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The run cannot start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run started: %1, %2, z = %3, %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the run did not start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the run is over</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Continue</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ready to start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paused — the CNC keeps the last correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fault — the CNC keeps the last correction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: “%2” — %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CNC</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CNC: none (add a correction output on the Devices page)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gauge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Diameters: typed in by hand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Parts done: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Machine: %1 (its own CNC, gauge and part cycle)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Press Start: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gauge: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 · CNC: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The new controller tuning took over at part %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A run is already going; stop it first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Continuing run %1 from part %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The machine “%1” is not offered; choose another.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose a machine.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ToolAuditModel</name>
    <message>
        <source>When</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Who</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool or material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Field</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Old</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ToolImportModel</name>
    <message>
        <source>Take from file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>In the table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Differences (table → file) or problems</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>new</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>same</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>different</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cannot be read</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to do</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Skipped</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ToolTableModel</name>
    <message>
        <source>Tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Section</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>d, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>b, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>h, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Overhang l, mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>E, MPa</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured k, N/mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measured by</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k_p, N/A</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k = 3EI/l³, N/mm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>l/d</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computed from the section, the overhang and E; a measured stiffness overrides it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>round</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rectangular</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Removed when you apply the changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied value: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove %1 tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>id: %1 is also used in row %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::ToolsPage</name>
    <message>
        <source>Not accepted: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>round</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rectangular</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (E %2 MPa)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Enter your name on the Settings page first: every applied change is recorded with it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: no operator name (Settings)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redo: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fix before applying: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Changed tools: %1 (highlighted). They are not stored until you apply them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>All changes are applied. Double-click a cell to edit it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select the tools to remove first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to apply.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>These rows need fixing first:
%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Applied. Audit entries written with your name: %1.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing was stored: %1
Your edits are still here.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not stored: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discard changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discard the pending changes of %1 tools? The stored table stays as it is.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pending changes discarded.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be imported: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tools imported from %1: %2, highlighted until you apply them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import cancelled; the table is unchanged.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported %1 tools to %2, including %3 change(s) not applied yet.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Exported %1 tools to %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New material %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Added %1 (E 210000 MPa): double-click to rename it and set E.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Select the material to remove first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Removed %1; tools keep their stored E.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit material</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: E %2 MPa stored; tools keep the E they have until you choose the material again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add tool</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Discard</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Young&apos;s modulus of each holder material. Choosing a material for a tool copies its E; every change here is stored at once and recorded in the audit.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Materials</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Audit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Take all from file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep all in table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Import</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 new, %2 different from the table, %3 the same, %4 cannot be read. Choose for each different tool whether to keep the table&apos;s values or take the file&apos;s; imported rows stay pending until you apply them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The tool table cannot be opened</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1&lt;br&gt;&lt;br&gt;The table is stored in the run history database; check the database on the Settings page.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply changes</source>
        <comment>button</comment>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n changed tool(s) on the Tools page</source>
        <translation>
            <numerusform>%n changed tool on the Tools page</numerusform>
            <numerusform>%n changed tools on the Tools page</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>tt::ui::UserSession</name>
    <message>
        <source>Operator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Engineer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quality</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Administrator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nobody is logged in</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::UsersDialog</name>
    <message>
        <source>Users</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Role</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Logs in with</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PIN (digits)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> failed log-ins</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> min</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PIN or password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add user</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set role</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set PIN or password</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Unlock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Remove</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Log-in rules</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lock out after</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lock-out lasts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Log out when idle for</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Apply the rules</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>locked until %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>active</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PIN</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not changed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 added.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is now %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>select a user first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New PIN or password of %1 stored.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 unlocked.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 removed.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Log-in rules stored.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>tt::ui::VerdictCounter</name>
    <message>
        <source>Good: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rework: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Scrap: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Yield: no part yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Yield: %1 % of %n part(s)</source>
        <translation>
            <numerusform>Yield: %1 % of %n part</numerusform>
            <numerusform>Yield: %1 % of %n parts</numerusform>
        </translation>
    </message>
    <message>
        <source>No part measured yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1: GOOD</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1: REWORK</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part %1: SCRAP</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
