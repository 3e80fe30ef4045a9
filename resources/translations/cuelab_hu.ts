<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="hu_HU">
<context>
    <name>QObject</name>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="29"/>
        <source>&amp;Velocities</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="30"/>
        <source>&amp;Spin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="31"/>
        <source>&amp;Trails</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="32"/>
        <source>&amp;Future Paths</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="33"/>
        <source>&amp;Event Markers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="34"/>
        <source>&amp;Ghost Balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="35"/>
        <source>&amp;Cue and Aim Line</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowPrivate.h" line="13"/>
        <source>CueLab setups (*.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="35"/>
        <source>Position of the ball&apos;s centre at t = 0, in metres</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="30"/>
        <source>The simulation failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="70"/>
        <source>v_rel %1, |J| %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="73"/>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="77"/>
        <source>v %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="75"/>
        <source>at %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/RackPresets.cpp" line="16"/>
        <source>Cue ball and one object ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/RackPresets.cpp" line="17"/>
        <source>9-ball diamond</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/RackPresets.cpp" line="18"/>
        <source>8-ball triangle (15 balls)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/RackPresets.cpp" line="19"/>
        <source>Newton&apos;s cradle (5 frozen balls)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::BallsPanel</name>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="58"/>
        <source>Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="58"/>
        <source>x₀ (m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="58"/>
        <source>y₀ (m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="58"/>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="58"/>
        <source>Position (m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="58"/>
        <source>|v| (m/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="59"/>
        <source>Set-up position along the length, in metres (double-click to edit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="60"/>
        <source>Set-up position across the width, in metres (double-click to edit)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="61"/>
        <source>Motion state at the current time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="62"/>
        <source>Position at the current time, in metres</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="63"/>
        <source>Speed at the current time, in m/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="77"/>
        <source>&amp;Add Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="78"/>
        <source>Add a ball on a free spot near the centre of the table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="79"/>
        <source>&amp;Remove Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="80"/>
        <source>Remove the selected ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="81"/>
        <source>D&amp;uplicate Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="82"/>
        <source>Add a copy of the selected ball next to it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="83"/>
        <source>Rac&amp;k</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="84"/>
        <source>Replace the balls by a standard rack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="94"/>
        <source>Rack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="182"/>
        <source>Ball id (double-click to rename)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="237"/>
        <source>Rename ball %1 to %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/BallsPanel.cpp" line="242"/>
        <source>Move ball %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::Document</name>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="90"/>
        <location filename="../../widgets/editor/Document.cpp" line="107"/>
        <source>Untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="175"/>
        <source>Move ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="194"/>
        <location filename="../../widgets/editor/Document.cpp" line="229"/>
        <source>There is no free place on the table for another ball.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="204"/>
        <source>Add ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="219"/>
        <source>Remove ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="237"/>
        <source>Duplicate ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="257"/>
        <source>Rack: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="258"/>
        <source>Clear the table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="262"/>
        <source>Place ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="264"/>
        <source>Aim at the rack</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/Document.cpp" line="280"/>
        <source>Reset physics to defaults</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::EventTableModel</name>
    <message>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="110"/>
        <source>Time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="111"/>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="112"/>
        <source>Agents</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="113"/>
        <source>Δt (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="114"/>
        <source>Key values</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="120"/>
        <source>Time of the event in seconds after the strike (exact: a root of a polynomial)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="121"/>
        <source>Seconds since the previous event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventTableModel.cpp" line="122"/>
        <source>Collisions: normal approach speed (m/s) and impulse (N·s); changes of motion: speed after (m/s)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::EventsPanel</name>
    <message>
        <location filename="../../widgets/editor/EventsPanel.cpp" line="47"/>
        <source>Show changes of motion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventsPanel.cpp" line="52"/>
        <source>List the changes of motion too (slide to roll, roll to stop, ...), not only strikes, collisions and pockets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/EventsPanel.cpp" line="61"/>
        <source>Select an event to jump to its time and see it in the Inspector</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::InspectorPanel</name>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="27"/>
        <source>Quantity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="27"/>
        <source>Value</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="57"/>
        <source>Select a ball or an event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="63"/>
        <source>State</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="65"/>
        <source>Position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="66"/>
        <source>Velocity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="67"/>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="68"/>
        <source>Spin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="68"/>
        <source>Angular velocity (ωx, ωy, ωz); ωz &gt; 0 is counter-clockwise seen from above</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="69"/>
        <source>Slip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="70"/>
        <source>Velocity of the contact point with the cloth, v + R (z × ω); zero when rolling</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="102"/>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="143"/>
        <source>Ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="102"/>
        <source>at t = %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="105"/>
        <source>Pocket</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="106"/>
        <source>Momentum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="107"/>
        <source>Kinetic energy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="108"/>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="154"/>
        <source>Translation plus rotation, I = 2/5 m R²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="109"/>
        <source>Radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="110"/>
        <source>Mass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="121"/>
        <source>Event %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="122"/>
        <source>Agents</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="123"/>
        <source>Time of impact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="124"/>
        <source>Exact time of the event: a root of the polynomial that describes the contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="125"/>
        <source>Since previous</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="127"/>
        <source>Contact point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="128"/>
        <source>Contact normal</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="128"/>
        <source>Unit normal from the first ball towards the other body</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="129"/>
        <source>Relative speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="129"/>
        <source>Normal approach speed just before contact</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="130"/>
        <source>Impulse</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="130"/>
        <source>Impulse on the first ball, table frame</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="131"/>
        <source>|Impulse|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="144"/>
        <source>Before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="145"/>
        <source>After</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="151"/>
        <source>Both balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="151"/>
        <source>Totals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="152"/>
        <source>Momentum before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="153"/>
        <source>Momentum after</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="154"/>
        <source>Kinetic energy before</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="155"/>
        <source>Kinetic energy after</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/InspectorPanel.cpp" line="156"/>
        <source>Energy change</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::MainWindow</name>
    <message>
        <location filename="../../app/window/MainWindow.cpp" line="93"/>
        <source>Not applied: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindow.cpp" line="111"/>
        <source>%1 fps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindow.cpp" line="137"/>
        <source>Balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindow.cpp" line="138"/>
        <source>Shot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindow.cpp" line="139"/>
        <source>Physics</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindow.cpp" line="141"/>
        <source>Events</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindow.cpp" line="142"/>
        <source>Inspector</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindow.cpp" line="181"/>
        <source>&amp;Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindow.cpp" line="201"/>
        <source>Frames per second the table view draws</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindow.cpp" line="206"/>
        <source>Simulating the edited setup</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <location filename="../../app/window/MainWindow.cpp" line="256"/>
        <source>%n event(s), at rest at %1</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <location filename="../../app/window/MainWindow.cpp" line="258"/>
        <source>%n event(s), stopped at the time limit</source>
        <translation type="unfinished">
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindow.cpp" line="259"/>
        <source>Cut short: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="63"/>
        <source>Unsaved Changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="63"/>
        <source>%1 has unsaved changes. Save them first?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="79"/>
        <source>Open Setup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="88"/>
        <source>Cannot Open Setup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="93"/>
        <source>Opened %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="103"/>
        <location filename="../../app/window/MainWindowFiles.cpp" line="108"/>
        <source>Cannot Open Example</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="103"/>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="111"/>
        <source>Example %1: save it to keep your changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="127"/>
        <source>untitled</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="129"/>
        <source>Save Setup As</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="139"/>
        <source>Cannot Save Setup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="144"/>
        <source>Saved %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="150"/>
        <source>%1[*] — CueLab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="163"/>
        <source>About CueLab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowFiles.cpp" line="164"/>
        <source>&lt;h3&gt;CueLab %1&lt;/h3&gt;&lt;p&gt;An exact, event-based billiards simulator and shot editor: every time of impact is a root of a polynomial.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="44"/>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="45"/>
        <source>&amp;New</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="47"/>
        <source>A new setup: a 9-ft table with a cue ball and one object ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="48"/>
        <source>&amp;Open…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="50"/>
        <source>Open &amp;Recent</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="53"/>
        <source>&amp;Examples</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="62"/>
        <source>Open the bundled example %1 as a new, untitled setup</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="66"/>
        <source>&amp;Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="68"/>
        <source>Save &amp;As…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="71"/>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="74"/>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="75"/>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="77"/>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="90"/>
        <source>Reset &amp;Physics to Defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="92"/>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="93"/>
        <source>&amp;Panels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="95"/>
        <source>&amp;Overlays</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="104"/>
        <source>&amp;Camera</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="105"/>
        <source>&amp;Top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="106"/>
        <source>&amp;Player</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="107"/>
        <source>&amp;Side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="114"/>
        <source>&amp;Full Screen</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="121"/>
        <source>&amp;Analysis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="122"/>
        <source>&amp;Playback</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="125"/>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="126"/>
        <source>&amp;About CueLab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../app/window/MainWindowMenus.cpp" line="127"/>
        <source>About &amp;Qt</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::PhysicsPanel</name>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="29"/>
        <source>The table: playing surface between the cushion noses in metres, pockets and cushions of the preset. The balls keep their size and place; a ball that would lie off the cloth refuses the change.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="30"/>
        <source>Pockets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="31"/>
        <source>Without pockets the rails are closed all round (a carom table never has pockets)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="32"/>
        <source>m/s²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="32"/>
        <source>Gravitational acceleration g in m/s² (9.81 on Earth)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="33"/>
        <source>Sliding friction between ball and cloth (dimensionless; 0.2, range 0.15-0.4, Alciatore)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="34"/>
        <source>Rolling resistance of the cloth (dimensionless; 0.01, range 0.005-0.015)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="35"/>
        <source>Spin friction about the vertical axis (dimensionless; 0.0127 slows side spin by about 10.9 rad/s²)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="37"/>
        <source>Frictionless</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="38"/>
        <source>Frictional (throw)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="39"/>
        <source>Ball-ball collision model: frictionless (spins unchanged) or with a Coulomb-limited tangential impulse that throws the object ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="40"/>
        <source>Ball-ball coefficient of restitution (dimensionless; 0.95, range 0.92-0.98)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="42"/>
        <source>Fixed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="43"/>
        <source>Speed-dependent (Alciatore)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="44"/>
        <source>Ball-ball friction: a fixed coefficient, or Alciatore&apos;s fit 0.00995 + 0.108 exp(-1.088 v) of the relative speed v in m/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="45"/>
        <source>Fixed ball-ball friction coefficient (dimensionless; 0.05)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="47"/>
        <source>Mirror</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="48"/>
        <source>Han 2005</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="49"/>
        <source>Ball-cushion model: mirror reflection scaled by restitution, or Han 2005 (contact above the equator, with friction)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="50"/>
        <source>Ball-cushion coefficient of restitution (dimensionless; 0.85, range 0.6-0.9)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="51"/>
        <source>Ball-cushion friction coefficient (dimensionless; 0.2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="52"/>
        <source>ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="52"/>
        <source>Frame timestep in milliseconds: one step of frame-by-frame playback (16.667 ms = 60 frames per second)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="53"/>
        <source>s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="53"/>
        <source>The simulation stops at this time in seconds at the latest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="54"/>
        <source>Reset to Defaults</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="55"/>
        <source>Set friction, restitution, models and gravity back to the defaults of the physics reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="57"/>
        <source>Table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="59"/>
        <source>Kind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="61"/>
        <source>Cloth</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="63"/>
        <source>μ slide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="64"/>
        <source>μ roll</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="65"/>
        <source>μ spin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="66"/>
        <source>Gravity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="67"/>
        <source>Ball-ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="69"/>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="75"/>
        <source>Model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="70"/>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="76"/>
        <source>Restitution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="71"/>
        <source>Friction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="72"/>
        <source>μ ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="73"/>
        <source>Ball-cushion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="77"/>
        <source>μ cushion</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="78"/>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="80"/>
        <source>Frame step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="81"/>
        <source>Stop at</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="92"/>
        <source>Change gravity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="93"/>
        <source>Change μ slide</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="94"/>
        <source>Change μ roll</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="95"/>
        <source>Change μ spin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="96"/>
        <source>Change ball-ball restitution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="97"/>
        <source>Change ball-ball friction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="98"/>
        <source>Change cushion restitution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="99"/>
        <source>Change cushion friction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="100"/>
        <source>Change the ball-ball model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="101"/>
        <source>Change the ball-ball friction law</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="102"/>
        <source>Change the cushion model</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="103"/>
        <source>Change the frame step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="104"/>
        <source>Change the time limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="106"/>
        <source>Change the table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="107"/>
        <source>Open the pockets</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/PhysicsPanel.cpp" line="107"/>
        <source>Close the pockets</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::RecentFiles</name>
    <message>
        <location filename="../../app/window/RecentFiles.cpp" line="43"/>
        <source>&amp;Clear List</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::ShotPanel</name>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="26"/>
        <source>Strike a ball at t = 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="27"/>
        <source>Without a strike the balls move only with the velocities and spins they are set up with.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="29"/>
        <source>The ball the cue strikes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="31"/>
        <source>m/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="31"/>
        <source>Cue speed V0 in m/s just before the tip meets the ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="35"/>
        <source>Heading of the cue in degrees: 0 = along +x (towards the foot rail), counter-clockwise positive</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="40"/>
        <source>Elevation of the cue above the cloth in degrees (masse and jump shots)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="41"/>
        <source>Side offset of the tip as a fraction of the ball radius R: + = right of centre (right english)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="42"/>
        <source>Height offset of the tip as a fraction of the ball radius R: + = above centre (follow), 0.4 R = natural roll</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="44"/>
        <source>kg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="44"/>
        <source>Mass of the cue in kg (a typical cue: 0.567 kg, 20 oz)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="49"/>
        <source>Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="53"/>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="57"/>
        <source>Heading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="58"/>
        <source>Elevation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="61"/>
        <source>Side</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="62"/>
        <source>Height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="65"/>
        <source>Tip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="66"/>
        <source>Cue mass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="68"/>
        <source>Add the cue strike</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="68"/>
        <source>Remove the cue strike</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="69"/>
        <source>Strike ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="70"/>
        <source>Change the cue speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="74"/>
        <source>Change the heading</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="76"/>
        <source>Change the cue elevation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="77"/>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="78"/>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="83"/>
        <source>Move the cue tip</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/ShotPanel.cpp" line="85"/>
        <source>Change the cue mass</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::TimelineSlider</name>
    <message>
        <location filename="../../widgets/editor/TimelineSlider.cpp" line="16"/>
        <source>Time since the strike; a tick marks every event</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::TipOffsetWidget</name>
    <message>
        <location filename="../../widgets/editor/TipOffsetWidget.cpp" line="16"/>
        <source>Cue tip offset on the ball&apos;s face, as the player sees it. Click or drag to place the tip; the dashed circle is the miscue limit (half the radius).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>cuelab::TransportBar</name>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="40"/>
        <source>&amp;Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="40"/>
        <source>Go to the start, t = 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="41"/>
        <source>&amp;Previous Event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="41"/>
        <source>Go to the previous event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="43"/>
        <source>Frame &amp;Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="43"/>
        <source>One frame back (the frame step is set in Physics)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="44"/>
        <location filename="../../widgets/editor/TransportBar.cpp" line="97"/>
        <source>&amp;Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="44"/>
        <source>Play or pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="46"/>
        <source>Frame &amp;Forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="46"/>
        <source>One frame forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="47"/>
        <source>&amp;Next Event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="47"/>
        <source>Go to the next event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="49"/>
        <source>&amp;End</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="49"/>
        <source>Go to the end, when every ball rests</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="53"/>
        <source>Current time and end time of the shot, in seconds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="57"/>
        <source>Playback speed: 1× is real time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="97"/>
        <source>&amp;Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <location filename="../../widgets/editor/TransportBar.cpp" line="117"/>
        <source>t = %1 s / %2 s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
