<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="hu_HU">
<context>
    <name>Arrangements</name>
    <message>
        <source>&amp;Reset Layout</source>
        <translation>Az elrendezés &amp;visszaállítása</translation>
    </message>
    <message>
        <source>&amp;Teach</source>
        <translation>&amp;Tanítás</translation>
    </message>
    <message>
        <source>&amp;Coach</source>
        <translation>&amp;Edzés</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Szerkesztés</translation>
    </message>
    <message>
        <source>Every panel back where the first start put it: the editor on the left, the events and explanations on the right, plots and comparisons hidden until asked for</source>
        <translation>Minden panel vissza oda, ahová az első indítás tette: balra a szerkesztő, jobbra az események és a magyarázatok, a grafikonok és az összehasonlítás rejtve, amíg nem kéri őket</translation>
    </message>
    <message>
        <source>For a lesson: the table, the Lesson notes, Explain and Plots</source>
        <translation>Órához: az asztal, a Lecke jegyzetei, a Magyarázat és a Grafikonok</translation>
    </message>
    <message>
        <source>For a shot on the table: the table, Shot with the whole tip picker, Analysis and Outcome</source>
        <translation>Egy ütés gyakorlásához: az asztal, az Ütés a teljes dákóhegy-választóval, az Elemzés és az Eredmény</translation>
    </message>
    <message>
        <source>For setting up: the table, Balls and Physics, Events</source>
        <translation>Beállításhoz: az asztal, a Golyók és a Fizika, az Események</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>&amp;Velocities</source>
        <translation>&amp;Sebességek</translation>
    </message>
    <message>
        <source>&amp;Spin</source>
        <translation>&amp;Pörgetés</translation>
    </message>
    <message>
        <source>&amp;Trails</source>
        <translation>&amp;Nyomvonalak</translation>
    </message>
    <message>
        <source>&amp;Future Paths</source>
        <translation>&amp;Jövőbeli pályák</translation>
    </message>
    <message>
        <source>&amp;Event Markers</source>
        <translation>&amp;Eseményjelölők</translation>
    </message>
    <message>
        <source>&amp;Ghost Balls</source>
        <translation>S&amp;zellemgolyók</translation>
    </message>
    <message>
        <source>&amp;Cue and Aim Line</source>
        <translation>&amp;Dákó és célzóvonal</translation>
    </message>
    <message>
        <source>CueLab setups (*.json);;All files (*)</source>
        <translation>CueLab-felállások (*.json);;Minden fájl (*)</translation>
    </message>
    <message>
        <source>Position of the ball&apos;s centre at t = 0, in metres</source>
        <translation>A golyó középpontjának helye t = 0-kor, méterben</translation>
    </message>
    <message>
        <source>The simulation failed: %1</source>
        <translation>A szimuláció nem sikerült: %1</translation>
    </message>
    <message>
        <source>v_rel %1, |J| %2</source>
        <translation>v_rel %1, |J| %2</translation>
    </message>
    <message>
        <source>, held (a push)</source>
        <translation>, tartós érintkezés (tolás)</translation>
    </message>
    <message>
        <source>v %1</source>
        <translation>v %1</translation>
    </message>
    <message>
        <source>at %1</source>
        <translation>%1-kor</translation>
    </message>
    <message>
        <source>Cue ball and one object ball</source>
        <translation>Fehér golyó és egy célgolyó</translation>
    </message>
    <message>
        <source>9-ball diamond</source>
        <translation>9-es rombusz</translation>
    </message>
    <message>
        <source>8-ball triangle (15 balls)</source>
        <translation>8-as háromszög (15 golyó)</translation>
    </message>
    <message>
        <source>Newton&apos;s cradle (5 frozen balls)</source>
        <translation>Newton-bölcső (5 egymáshoz simuló golyó)</translation>
    </message>
    <message>
        <source>Move ball %1</source>
        <translation>A(z) %1 golyó áthelyezése</translation>
    </message>
    <message>
        <source>Set the velocity of ball %1</source>
        <translation>A(z) %1 golyó sebességének beállítása</translation>
    </message>
    <message>
        <source>Set the spin of ball %1</source>
        <translation>A(z) %1 golyó pörgetésének beállítása</translation>
    </message>
    <message>
        <source>Set the radius of ball %1</source>
        <translation>A(z) %1 golyó sugarának beállítása</translation>
    </message>
    <message>
        <source>Set the mass of ball %1</source>
        <translation>A(z) %1 golyó tömegének beállítása</translation>
    </message>
    <message>
        <source>Rename ball %1</source>
        <translation>A(z) %1 golyó átnevezése</translation>
    </message>
    <message>
        <source>Analysis</source>
        <translation>Elemzés</translation>
    </message>
    <message>
        <source>Scan &amp;tolerances</source>
        <translation>&amp;Tűrések letapogatása</translation>
    </message>
    <message>
        <source>The windows of heading, speed, elevation and tip offset in which the shot still meets the goal</source>
        <translation>Az irány, a sebesség, az emelés és a dákóvég-eltolás ablakai, amelyekben az ütés még teljesíti a célt</translation>
    </message>
    <message>
        <source>&amp;Map tip offsets</source>
        <translation>A dákóvég-eltolások &amp;térképe</translation>
    </message>
    <message>
        <source>Simulate the shot for every tip offset within the miscue limit and colour each by its outcome</source>
        <translation>Az ütés szimulálása minden, a lecsúszási határon belüli dákóvég-eltolásra, mindegyik az eredménye szerint színezve</translation>
    </message>
    <message>
        <source>&amp;Cancel analysis</source>
        <translation>Az elemzés &amp;megszakítása</translation>
    </message>
    <message>
        <source>Stop the running scan or map</source>
        <translation>A futó letapogatás vagy térképezés leállítása</translation>
    </message>
    <message>
        <source>Analysis &amp;panel</source>
        <translation>Elemzés&amp;panel</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>Összehasonlítás</translation>
    </message>
    <message>
        <source>Compare &amp;Methods…</source>
        <translation>A módszerek ö&amp;sszehasonlítása…</translation>
    </message>
    <message>
        <source>Run the shot with the 2011 discrete method or Box2D and measure it against the exact simulation</source>
        <translation>Az ütés lefuttatása a 2011-es diszkrét módszerrel vagy a Box2D-vel, és összemérése a pontos szimulációval</translation>
    </message>
    <message>
        <source>Export explanation</source>
        <translation>A magyarázat exportálása</translation>
    </message>
    <message>
        <source>This shot has no events to explain yet.</source>
        <translation>Ennek az ütésnek még nincs magyarázható eseménye.</translation>
    </message>
    <message>
        <source>The selected event</source>
        <translation>A kijelölt esemény</translation>
    </message>
    <message>
        <source>Every collision of the shot</source>
        <translation>Az ütés minden ütközése</translation>
    </message>
    <message>
        <source>Explain:</source>
        <translation>Magyarázat:</translation>
    </message>
    <message>
        <source>HTML (*.html);;Markdown (*.md)</source>
        <translation>HTML (*.html);;Markdown (*.md)</translation>
    </message>
    <message>
        <source>Explain</source>
        <translation>Magyarázat</translation>
    </message>
    <message>
        <source>Lesson</source>
        <translation>Lecke</translation>
    </message>
    <message>
        <source>&amp;Explanation…</source>
        <translation>&amp;Magyarázat…</translation>
    </message>
    <message>
        <source>Write the selected event&apos;s mathematics, or every collision&apos;s, as HTML or Markdown</source>
        <translation>A kijelölt esemény vagy minden ütközés matematikájának kiírása HTML- vagy Markdown-fájlba</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 cm</source>
        <translation>%1 cm</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>%1 µm</source>
        <translation>%1 µm</translation>
    </message>
    <message>
        <source>no event %1 in this shot</source>
        <translation>ebben az ütésben nincs %1. esemény</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Collision &amp;Arrows</source>
        <translation>Ütközési &amp;nyilak</translation>
    </message>
    <message>
        <source>In the table view: the selected collision&apos;s contact point, contact normal and impulse, and each ball&apos;s momentum before and after, as labelled arrows</source>
        <translation>Az asztalnézetben: a kijelölt ütközés érintkezési pontja, érintkezési normálisa és erőlökése, valamint minden golyó lendülete előtte és utána, feliratozott nyilakként</translation>
    </message>
    <message>
        <source>f(τ), the gap, from t₀ = %1 s</source>
        <translation>f(τ), a rés, t₀ = %1 s-tól</translation>
    </message>
    <message>
        <source>τ = %1 s</source>
        <translation>τ = %1 s</translation>
    </message>
    <message>
        <source>blue: f(τ); dashed: f = 0; red dot: the chosen root τ* = %1 s</source>
        <translation>kék: f(τ); szaggatott: f = 0; piros pont: a választott gyök, τ* = %1 s</translation>
    </message>
    <message>
        <source>Time of impact</source>
        <translation>Az ütközés időpontja</translation>
    </message>
    <message>
        <source>Momentum and energy</source>
        <translation>Lendület és energia</translation>
    </message>
    <message>
        <source>Predict</source>
        <translation>Jóslás</translation>
    </message>
</context>
<context>
    <name>cuelab</name>
    <message>
        <source>Cancel</source>
        <translation>Mégse</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportálás</translation>
    </message>
    <message>
        <source>Exported %1</source>
        <translation>Exportálva: %1</translation>
    </message>
    <message>
        <source>Export cancelled: nothing was written</source>
        <translation>Az exportálás megszakítva: semmi sem íródott ki</translation>
    </message>
    <message>
        <source>There is no simulation to export yet.</source>
        <translation>Még nincs exportálható szimuláció.</translation>
    </message>
    <message>
        <source>Export the View as PNG</source>
        <translation>A nézet exportálása PNG-képként</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source>Image width in pixels</source>
        <translation>A kép szélessége képpontban</translation>
    </message>
    <message>
        <source>Image height in pixels</source>
        <translation>A kép magassága képpontban</translation>
    </message>
    <message>
        <source>Top (whole table)</source>
        <translation>Felülről (az egész asztal)</translation>
    </message>
    <message>
        <source>Player (behind the cue ball)</source>
        <translation>Játékos (a fehér golyó mögül)</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Oldalról</translation>
    </message>
    <message>
        <source>Width:</source>
        <translation>Szélesség:</translation>
    </message>
    <message>
        <source>Height:</source>
        <translation>Magasság:</translation>
    </message>
    <message>
        <source>Camera:</source>
        <translation>Kamera:</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-képek (*.png)</translation>
    </message>
    <message>
        <source>Export the Shot Diagram as PDF</source>
        <translation>Az ütésábra exportálása PDF-ként</translation>
    </message>
    <message>
        <source>PDF documents (*.pdf)</source>
        <translation>PDF-dokumentumok (*.pdf)</translation>
    </message>
    <message>
        <source>Export the Shot Diagram as SVG</source>
        <translation>Az ütésábra exportálása SVG-ként</translation>
    </message>
    <message>
        <source>SVG images (*.svg)</source>
        <translation>SVG-képek (*.svg)</translation>
    </message>
    <message>
        <source>Drawing the shot diagram...</source>
        <translation>Az ütésábra rajzolása…</translation>
    </message>
    <message>
        <source>Export the Trajectory</source>
        <translation>A pálya exportálása</translation>
    </message>
    <message>
        <source>Frame step (ms):</source>
        <translation>Képkockalépés (ms):</translation>
    </message>
    <message>
        <source>View as &amp;PNG...</source>
        <translation>Nézet &amp;PNG-ként…</translation>
    </message>
    <message>
        <source>Shot Diagram as &amp;SVG...</source>
        <translation>Ütésábra &amp;SVG-ként…</translation>
    </message>
    <message>
        <source>A print-style top-down diagram: numbered balls, paths, contacts with their times, the outcome</source>
        <translation>Nyomtatható, felülnézeti ábra: számozott golyók, pályák, az érintkezések időpontjukkal, az eredmény</translation>
    </message>
    <message>
        <source>Shot Diagram as P&amp;DF...</source>
        <translation>Ütésábra P&amp;DF-ként…</translation>
    </message>
    <message>
        <source>The shot diagram on an A4 page</source>
        <translation>Az ütésábra egy A4-es oldalon</translation>
    </message>
    <message>
        <source>Lesson &amp;Report (PDF)...</source>
        <translation>Lecke&amp;jegyzet (PDF)…</translation>
    </message>
    <message>
        <source>Export the Lesson Report</source>
        <translation>A leckejegyzet exportálása</translation>
    </message>
    <message>
        <source>Writing the lesson report...</source>
        <translation>A leckejegyzet írása…</translation>
    </message>
    <message>
        <source>Writing the trajectory...</source>
        <translation>A pálya írása…</translation>
    </message>
    <message>
        <source>Writing the events...</source>
        <translation>Az események írása…</translation>
    </message>
    <message>
        <source>Every ball&apos;s state at every frame (a frame step you choose) and at every event</source>
        <translation>Minden golyó állapota minden képkockán (választott képkockalépéssel) és minden eseménynél</translation>
    </message>
    <message>
        <source>Every event with its agents&apos; states before and after</source>
        <translation>Minden esemény, a résztvevők előtte és utána vett állapotával</translation>
    </message>
    <message>
        <source>Current view</source>
        <translation>Jelenlegi nézet</translation>
    </message>
    <message>
        <source>The table view&apos;s own camera, time, overlays, layers and selection, exactly as shown</source>
        <translation>Az asztalnézet saját kamerája, ideje, rétegei, rárajzolt elemei és kijelölése, pontosan úgy, ahogy látszik</translation>
    </message>
    <message>
        <source>Render the table view at a chosen size into a PNG image, from its current camera or a preset</source>
        <translation>Az asztal nézetének kirajzolása választott méretben egy PNG-képbe, a jelenlegi kamerából vagy egy előre beállított nézetből</translation>
    </message>
    <message>
        <source>p %1 = %2 N·s</source>
        <translation>p %1 = %2 N·s</translation>
    </message>
    <message>
        <source>p′ %1 = %2 N·s</source>
        <translation>p′ %1 = %2 N·s</translation>
    </message>
    <message>
        <source>J = %1 N·s</source>
        <translation>J = %1 N·s</translation>
    </message>
    <message>
        <source>n</source>
        <translation>n</translation>
    </message>
    <message>
        <source>J = %1 N·s, vertical %2 N·s</source>
        <translation>J = %1 N·s, függőleges %2 N·s</translation>
    </message>
    <message>
        <source>contact</source>
        <translation>érintkezés</translation>
    </message>
    <message>
        <source>Arrows: 1 N·s = %1 m</source>
        <translation>Nyilak: 1 N·s = %1 m</translation>
    </message>
    <message>
        <source>A printable report: the diagram, the lesson&apos;s notes, the shot and physics, the outcome, the key collision derived, the event table, the plots</source>
        <translation>Nyomtatható jelentés: az ábra, a lecke jegyzetei, az ütés és a fizika, a eredmény, a kulcsütközés levezetése, az eseménytáblázat, a grafikonok</translation>
    </message>
    <message>
        <source>recorded %1</source>
        <translation>rögzített %1</translation>
    </message>
    <message>
        <source>Recording</source>
        <translation>Felvétel</translation>
    </message>
    <message>
        <source>Open Recording</source>
        <translation>Felvétel megnyitása</translation>
    </message>
    <message>
        <source>%1: the recorded balls do not fit on the table</source>
        <translation>%1: a rögzített golyók nem férnek el az asztalon</translation>
    </message>
    <message>
        <source>The current shot has no ball &quot;%1&quot;. Start a new shot from the recording (its table, its balls where they were first tracked and a strike guessed from their first motion)?</source>
        <translation>A mostani ütésben nincs „%1” golyó. Induljon új ütés a felvételből (az asztala, a golyói az első követett helyükön, és az első mozgásukból becsült ütés)?</translation>
    </message>
    <message>
        <source>Opened the recording %1</source>
        <translation>Megnyitva a felvétel: %1</translation>
    </message>
    <message>
        <source>Open &amp;Recording…</source>
        <translation>&amp;Felvétel megnyitása…</translation>
    </message>
    <message>
        <source>Open a tracked shot (cuelab-recording JSON or CSV) and show it against the simulation</source>
        <translation>Követett ütés megnyitása (cuelab-recording JSON vagy CSV) és összevetése a szimulációval</translation>
    </message>
    <message>
        <source>Recordings (*.json *.csv);;All files (*)</source>
        <translation>Felvételek (*.json *.csv);;Minden fájl (*)</translation>
    </message>
    <message>
        <source>Fit Strike to Recording</source>
        <translation>Ütés illesztése a felvételhez</translation>
    </message>
    <message>
        <source>Find the strike whose simulation follows the open recording best (one undoable edit)</source>
        <translation>Az ütés megkeresése, amelynek szimulációja a legjobban követi a megnyitott felvételt (egy visszavonható szerkesztés)</translation>
    </message>
    <message>
        <source>page %1 of %2</source>
        <translation>%1. oldal / %2</translation>
    </message>
    <message>
        <source>Shot</source>
        <translation>Ütés</translation>
    </message>
    <message>
        <source>Lesson</source>
        <translation>Lecke</translation>
    </message>
    <message>
        <source>(This setup has no notes.)</source>
        <translation>(Ehhez a felálláshoz nincs jegyzet.)</translation>
    </message>
    <message>
        <source>Note: these notes were written for the shot before these changes: %1. The tables and figures of this report are the shot as it is now.</source>
        <translation>Figyelem: ezek a jegyzetek az ütés alábbi változtatások előtti állapotához készültek: %1. A jelentés táblázatai és ábrái az ütést mostani állapotában mutatják.</translation>
    </message>
    <message>
        <source>The shot</source>
        <translation>Az ütés</translation>
    </message>
    <message>
        <source>The physics</source>
        <translation>A fizika</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>Eredmény</translation>
    </message>
    <message>
        <source>Struck ball: %1</source>
        <translation>Megütött golyó: %1</translation>
    </message>
    <message>
        <source>none (no shot)</source>
        <translation>nincs (nincs ütés)</translation>
    </message>
    <message>
        <source>First contact: %1</source>
        <translation>Első érintkezés: %1</translation>
    </message>
    <message>
        <source>%1 at %2 s</source>
        <translation>%1, %2 s-nál</translation>
    </message>
    <message>
        <source>none</source>
        <translation>nincs</translation>
    </message>
    <message>
        <source>Cushions before the first contact: %1</source>
        <translation>Mantinelek az első érintkezés előtt: %1</translation>
    </message>
    <message>
        <source>%1 in the %2 at %3 s</source>
        <translation>%1: %2ban, %3 s-nál</translation>
    </message>
    <message>
        <source>Pocketed: %1</source>
        <translation>Lyukba esett: %1</translation>
    </message>
    <message>
        <source>Struck ball pocketed: %1</source>
        <translation>A megütött golyó lyukba esett: %1</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>igen</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nem</translation>
    </message>
    <message>
        <source>The shot ends at %1 s, after %2 events.</source>
        <translation>Az ütés %1 s-nál ér véget, %2 esemény után.</translation>
    </message>
    <message>
        <source>Balls: cushion contacts and final positions</source>
        <translation>Golyók: mantinelérintések és végső helyzetek</translation>
    </message>
    <message>
        <source>ball</source>
        <translation>golyó</translation>
    </message>
    <message>
        <source>cushions</source>
        <translation>mantinelek</translation>
    </message>
    <message>
        <source>state</source>
        <translation>állapot</translation>
    </message>
    <message>
        <source>position x, y (m)</source>
        <translation>helyzet x, y (m)</translation>
    </message>
    <message>
        <source>in the %1</source>
        <translation>%1ban</translation>
    </message>
    <message>
        <source>The key collision, derived</source>
        <translation>A kulcsütközés levezetése</translation>
    </message>
    <message>
        <source>This shot has no collision.</source>
        <translation>Ebben az ütésben nincs ütközés.</translation>
    </message>
    <message>
        <source>Model: %1</source>
        <translation>Modell: %1</translation>
    </message>
    <message>
        <source>… the rest of the derivation: File → Export → Explanation.</source>
        <translation>… a levezetés többi része: Fájl → Exportálás → Magyarázat.</translation>
    </message>
    <message>
        <source>Events</source>
        <translation>Események</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>idő (s)</translation>
    </message>
    <message>
        <source>type</source>
        <translation>típus</translation>
    </message>
    <message>
        <source>balls</source>
        <translation>golyók</translation>
    </message>
    <message>
        <source>cushion / pocket</source>
        <translation>mantinel / lyuk</translation>
    </message>
    <message>
        <source>speed before → after (m/s)</source>
        <translation>sebesség előtte → utána (m/s)</translation>
    </message>
    <message>
        <source>Plots against time</source>
        <translation>Grafikonok az idő függvényében</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Sebesség</translation>
    </message>
    <message>
        <source>Slip speed at the cloth</source>
        <translation>Csúszási sebesség a posztón</translation>
    </message>
    <message>
        <source>Side spin ωz</source>
        <translation>Oldalpörgés ωz</translation>
    </message>
    <message>
        <source>Kinetic energy</source>
        <translation>Mozgási energia</translation>
    </message>
    <message>
        <source>%1: there is no simulation to report</source>
        <translation>%1: nincs jelenthető szimuláció</translation>
    </message>
    <message>
        <source>%1: cannot write the file: %2</source>
        <translation>%1: a fájl nem írható: %2</translation>
    </message>
    <message>
        <source>CueLab lesson report</source>
        <translation>CueLab leckejelentés</translation>
    </message>
    <message>
        <source>%1: cannot draw the PDF</source>
        <translation>%1: a PDF nem rajzolható meg</translation>
    </message>
    <message>
        <source>CueLab lesson report — %1</source>
        <translation>CueLab leckejelentés — %1</translation>
    </message>
    <message>
        <source>untitled shot</source>
        <translation>névtelen ütés</translation>
    </message>
    <message>
        <source>Struck ball</source>
        <translation>Megütött golyó</translation>
    </message>
    <message>
        <source>Cue speed</source>
        <translation>Dákósebesség</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Irány</translation>
    </message>
    <message>
        <source>Tip offset, side</source>
        <translation>Dákóvég eltolása, oldalt</translation>
    </message>
    <message>
        <source>R (+ right)</source>
        <translation>R (+ jobbra)</translation>
    </message>
    <message>
        <source>Tip offset, height</source>
        <translation>Dákóvég eltolása, magasság</translation>
    </message>
    <message>
        <source>R (+ above centre)</source>
        <translation>R (+ a közép fölött)</translation>
    </message>
    <message>
        <source>Cue elevation</source>
        <translation>Dákó emelése</translation>
    </message>
    <message>
        <source>Cue mass</source>
        <translation>Dákótömeg</translation>
    </message>
    <message>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <source>Squirt (cue end mass)</source>
        <translation>Kitérés (dákóvég tömege)</translation>
    </message>
    <message>
        <source>g</source>
        <translation>g</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Asztal</translation>
    </message>
    <message>
        <source>open</source>
        <translation>nyitva</translation>
    </message>
    <message>
        <source>closed</source>
        <translation>zárva</translation>
    </message>
    <message>
        <source>Sliding friction μs</source>
        <translation>Csúszási súrlódás μs</translation>
    </message>
    <message>
        <source>Rolling resistance μr</source>
        <translation>Gördülési ellenállás μr</translation>
    </message>
    <message>
        <source>Spin friction μsp</source>
        <translation>Pörgési súrlódás μsp</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Nehézségi gyorsulás</translation>
    </message>
    <message>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <source>, μb from Alciatore&apos;s fit</source>
        <translation>, μb Alciatore illesztéséből</translation>
    </message>
    <message>
        <source>, μb = %1</source>
        <translation>, μb = %1</translation>
    </message>
    <message>
        <source>Ball-ball model</source>
        <translation>Golyó–golyó modell</translation>
    </message>
    <message>
        <source>Ball-ball restitution e</source>
        <translation>Golyó–golyó ütközési szám e</translation>
    </message>
    <message>
        <source>Ball-cushion model</source>
        <translation>Golyó–mantinel modell</translation>
    </message>
    <message>
        <source>Cushion restitution e</source>
        <translation>Mantinel ütközési száma e</translation>
    </message>
    <message>
        <source>Cushion friction μ</source>
        <translation>Mantinel súrlódása μ</translation>
    </message>
    <message>
        <source>the cue strike was removed</source>
        <translation>a dákóütés megszűnt</translation>
    </message>
    <message>
        <source>a cue strike was added</source>
        <translation>dákóütés került be</translation>
    </message>
    <message>
        <source>the balls (positions, motion or sizes)</source>
        <translation>a golyók (helyzet, mozgás vagy méret)</translation>
    </message>
    <message>
        <source>bottom-left pocket</source>
        <translation>bal alsó lyuk</translation>
    </message>
    <message>
        <source>bottom-right pocket</source>
        <translation>jobb alsó lyuk</translation>
    </message>
    <message>
        <source>top-left pocket</source>
        <translation>bal felső lyuk</translation>
    </message>
    <message>
        <source>top-right pocket</source>
        <translation>jobb felső lyuk</translation>
    </message>
    <message>
        <source>bottom side pocket</source>
        <translation>alsó középső lyuk</translation>
    </message>
    <message>
        <source>top side pocket</source>
        <translation>felső középső lyuk</translation>
    </message>
    <message>
        <source>bottom rail</source>
        <translation>alsó mantinel</translation>
    </message>
    <message>
        <source>top rail</source>
        <translation>felső mantinel</translation>
    </message>
    <message>
        <source>left rail</source>
        <translation>bal mantinel</translation>
    </message>
    <message>
        <source>right rail</source>
        <translation>jobb mantinel</translation>
    </message>
    <message>
        <source>left half</source>
        <translation>bal fele</translation>
    </message>
    <message>
        <source>right half</source>
        <translation>jobb fele</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>jaw of the %1, %2</source>
        <translation>%1 pofája, %2</translation>
    </message>
    <message>
        <source>facing of the %1, %2</source>
        <translation>%1 oldallapja, %2</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>1 cushion</source>
        <translation>1 mantinel</translation>
    </message>
    <message>
        <source>%1 cushions</source>
        <translation>%1 mantinel</translation>
    </message>
    <message>
        <source>no shot</source>
        <translation>nincs ütés</translation>
    </message>
    <message>
        <source>%1 → %2 at %3, %4 before</source>
        <translation>%1 → %2, %3-nál, előtte %4</translation>
    </message>
    <message>
        <source>%1 touched no ball, %2</source>
        <translation>%1 nem ért golyót, %2</translation>
    </message>
    <message>
        <source>%1 (%2, %3)</source>
        <translation>%1 (%2, %3)</translation>
    </message>
    <message>
        <source>; pocketed: %1</source>
        <translation>; lyukba esett: %1</translation>
    </message>
    <message>
        <source>; %1 pocketed too</source>
        <translation>; %1 is lyukba esett</translation>
    </message>
    <message>
        <source>%1, %2 × %3 m</source>
        <translation>%1, %2 × %3 m</translation>
    </message>
    <message>
        <source>Pockets</source>
        <translation>Lyukak</translation>
    </message>
    <message>
        <source>dots: the recorded samples of %1, a colour per ball as in the Recording dock</source>
        <translation>pontok: %1 rögzített mintái, golyónként egy szín, mint a Felvétel panelen</translation>
    </message>
    <message>
        <source>Heading (°)</source>
        <translation>Irány (°)</translation>
    </message>
    <message>
        <source>Cue speed (m/s)</source>
        <translation>Dákósebesség (m/s)</translation>
    </message>
    <message>
        <source>Cue elevation (°)</source>
        <translation>Dákó emelése (°)</translation>
    </message>
    <message>
        <source>Tip offset, side (R)</source>
        <translation>Dákóvég eltolása, oldalt (R)</translation>
    </message>
    <message>
        <source>Tip offset, height (R)</source>
        <translation>Dákóvég eltolása, magasság (R)</translation>
    </message>
    <message>
        <source>Cue mass (kg)</source>
        <translation>Dákótömeg (kg)</translation>
    </message>
    <message>
        <source>Cue end mass (kg)</source>
        <translation>Dákóvég tömege (kg)</translation>
    </message>
    <message>
        <source>Gravity (m/s²)</source>
        <translation>Nehézségi gyorsulás (m/s²)</translation>
    </message>
    <message>
        <source>Ball-ball friction μb</source>
        <translation>Golyó–golyó súrlódás μb</translation>
    </message>
    <message>
        <source>Table length (m)</source>
        <translation>Asztal hossza (m)</translation>
    </message>
    <message>
        <source>Table width (m)</source>
        <translation>Asztal szélessége (m)</translation>
    </message>
    <message>
        <source>Cushion height (m)</source>
        <translation>Mantinel magassága (m)</translation>
    </message>
    <message>
        <source>Frame step (s)</source>
        <translation>Képkocka-lépés (s)</translation>
    </message>
    <message>
        <source>Time limit (s)</source>
        <translation>Időkorlát (s)</translation>
    </message>
    <message>
        <source>x (m)</source>
        <translation>x (m)</translation>
    </message>
    <message>
        <source>y (m)</source>
        <translation>y (m)</translation>
    </message>
    <message>
        <source>vx (m/s)</source>
        <translation>vx (m/s)</translation>
    </message>
    <message>
        <source>vy (m/s)</source>
        <translation>vy (m/s)</translation>
    </message>
    <message>
        <source>ωx (rad/s)</source>
        <translation>ωx (rad/s)</translation>
    </message>
    <message>
        <source>ωy (rad/s)</source>
        <translation>ωy (rad/s)</translation>
    </message>
    <message>
        <source>ωz (rad/s)</source>
        <translation>ωz (rad/s)</translation>
    </message>
    <message>
        <source>radius (m)</source>
        <translation>sugár (m)</translation>
    </message>
    <message>
        <source>mass (kg)</source>
        <translation>tömeg (kg)</translation>
    </message>
    <message>
        <source>Ball %1, %2</source>
        <translation>%1 golyó, %2</translation>
    </message>
    <message>
        <source>Cushion model&apos;s %1</source>
        <translation>A mantinelmodell %1 paramétere</translation>
    </message>
    <message>
        <source>Export Video</source>
        <translation>Videó exportálása</translation>
    </message>
    <message>
        <source>× slower</source>
        <translation>× lassítva</translation>
    </message>
    <message>
        <source>How many times slower than real time the shot plays (1 = real time; 8: one second of the shot lasts eight seconds of video)</source>
        <translation>Hányszor lassabban fut a lövés a valós időnél (1 = valós idő; 8: a lövés egy másodperce nyolc másodpercnyi videó)</translation>
    </message>
    <message>
        <source> frames/s</source>
        <translation> képkocka/s</translation>
    </message>
    <message>
        <source>Frames per second of the video (a GIF&apos;s frame times are in hundredths of a second: 30 plays at 33.3)</source>
        <translation>A videó képkockái másodpercenként (a GIF képkockaideje századmásodperc: a 30 33,3-ként játszódik le)</translation>
    </message>
    <message>
        <source>Video width in pixels (MP4 and WebM round it down to an even number)</source>
        <translation>A videó szélessége képpontban (MP4 és WebM esetén lefelé kerekítve páros számra)</translation>
    </message>
    <message>
        <source>Video height in pixels (MP4 and WebM round it down to an even number)</source>
        <translation>A videó magassága képpontban (MP4 és WebM esetén lefelé kerekítve páros számra)</translation>
    </message>
    <message>
        <source>The view as it is now: its camera, overlays, arrows and labels, with the time on every frame.</source>
        <translation>A nézet, ahogy most látszik: kamerája, rátétei, nyilai és feliratai, minden képkockán az idővel.</translation>
    </message>
    <message>
        <source>Slow motion</source>
        <translation>Lassítás</translation>
    </message>
    <message>
        <source>Frame rate</source>
        <translation>Képkockasebesség</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Szélesség</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Magasság</translation>
    </message>
    <message>
        <source>Writing %1…</source>
        <translation>%1 írása…</translation>
    </message>
    <message>
        <source>&amp;Video (MP4, WebM, GIF)…</source>
        <translation>&amp;Videó (MP4, WebM, GIF)…</translation>
    </message>
    <message>
        <source>Write the table view as it plays, slowed down, with the time on screen</source>
        <translation>Az asztalnézet lejátszás közben, lassítva, az idővel a képen</translation>
    </message>
    <message>
        <source>MP4 video (*.mp4);;WebM video (*.webm);;Animated GIF (*.gif)</source>
        <translation>MP4-videó (*.mp4);;WebM-videó (*.webm);;Animált GIF (*.gif)</translation>
    </message>
</context>
<context>
    <name>cuelab::AnalysisPanel</name>
    <message>
        <source>first contact: %1</source>
        <translation>első érintkezés: %1</translation>
    </message>
    <message>
        <source>pocketed: %1</source>
        <translation>lyukba esett: %1</translation>
    </message>
    <message>
        <source>none</source>
        <translation>nincs</translation>
    </message>
    <message>
        <source>%1 events, at rest at %2 s</source>
        <translation>%1 esemény, nyugalomban: %2 s</translation>
    </message>
    <message>
        <source>Click to load this shot.</source>
        <translation>Kattintson az ütés betöltéséhez.</translation>
    </message>
    <message>
        <source>e.g. pot:1@pocket-tr,no-scratch</source>
        <translation>pl. pot:1@pocket-tr,no-scratch</translation>
    </message>
    <message>
        <source>What the shot should do, terms separated by commas, all must hold:
pot:BALL or pot:BALL@POCKET — the ball is pocketed (in that pocket)
first:BALL — the struck ball hits BALL first
no-scratch — the struck ball stays on the table
in:BALL@X0:Y0:X1:Y1 — the ball ends inside that rectangle (m)
cushions:BALL=N (or &lt;=N, &gt;=N) — cushion hits of the ball, jaws included
!TERM — the term does not hold</source>
        <translation>Mit kell tennie az ütésnek; a feltételeket vessző választja el, mindnek teljesülnie kell:
pot:BALL vagy pot:BALL@POCKET — a golyó lyukba esik (abba a lyukba)
first:BALL — a megütött golyó először a BALL golyót találja el
no-scratch — a megütött golyó az asztalon marad
in:BALL@X0:Y0:X1:Y1 — a golyó abban a téglalapban áll meg (m)
cushions:BALL=N (vagy &lt;=N, &gt;=N) — a golyó mantinelérintései, a lyukpofákkal együtt
!TERM — a feltétel nem teljesül</translation>
    </message>
    <message>
        <source>From shot</source>
        <translation>Az ütésből</translation>
    </message>
    <message>
        <source>Set the goal to what the current shot does (the ball it pots, and no scratch)</source>
        <translation>A cél beállítása arra, amit az aktuális ütés tesz (a golyó, amelyet lyukba juttat, és a fehér nem esik be)</translation>
    </message>
    <message>
        <source>Tolerance around the current shot</source>
        <translation>Tűrés az aktuális ütés körül</translation>
    </message>
    <message>
        <source>Scan</source>
        <translation>Letapogatás</translation>
    </message>
    <message>
        <source>Scan heading (±2°), speed (±50%), elevation (±10°) and the tip offsets (±0.5 R) one at a time around their current values: the window in which the shot still meets the goal</source>
        <translation>Az irány (±2°), a sebesség (±50%), az emelés (±10°) és a dákóvég-eltolások (±0,5 R) letapogatása egyenként az aktuális értékük körül: az ablak, amelyben az ütés még teljesíti a célt</translation>
    </message>
    <message>
        <source>Outcome map</source>
        <translation>Eredménytérkép</translation>
    </message>
    <message>
        <source>Tip offset (side × height, within the miscue limit)</source>
        <translation>Dákóvég-eltolás (oldal × magasság, a lecsúszási határon belül)</translation>
    </message>
    <message>
        <source>Any two parameters</source>
        <translation>Bármely két paraméter</translation>
    </message>
    <message>
        <source>What the map&apos;s axes are</source>
        <translation>Mik a térkép tengelyei</translation>
    </message>
    <message>
        <source>Axes</source>
        <translation>Tengelyek</translation>
    </message>
    <message>
        <source>The key along the map&apos;s horizontal axis</source>
        <translation>A térkép vízszintes tengelyén változó kulcs</translation>
    </message>
    <message>
        <source>The key along the map&apos;s vertical axis</source>
        <translation>A térkép függőleges tengelyén változó kulcs</translation>
    </message>
    <message>
        <source>First value of the horizontal axis, in the key&apos;s unit</source>
        <translation>A vízszintes tengely első értéke, a kulcs mértékegységében</translation>
    </message>
    <message>
        <source>Last value of the horizontal axis, in the key&apos;s unit</source>
        <translation>A vízszintes tengely utolsó értéke, a kulcs mértékegységében</translation>
    </message>
    <message>
        <source>First value of the vertical axis, in the key&apos;s unit</source>
        <translation>A függőleges tengely első értéke, a kulcs mértékegységében</translation>
    </message>
    <message>
        <source>Last value of the vertical axis, in the key&apos;s unit</source>
        <translation>A függőleges tengely utolsó értéke, a kulcs mértékegységében</translation>
    </message>
    <message>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <source>Cells along each axis (a 101 × 101 map is about 10 000 shots)</source>
        <translation>Cellák tengelyenként (egy 101 × 101-es térkép kb. 10 000 ütés)</translation>
    </message>
    <message>
        <source>Map</source>
        <translation>Térkép</translation>
    </message>
    <message>
        <source>Simulate every cell of the map; the colours stream in</source>
        <translation>A térkép minden cellájának szimulálása; a színek folyamatosan érkeznek</translation>
    </message>
    <message>
        <source>Cells</source>
        <translation>Cellák</translation>
    </message>
    <message>
        <source>Each cell is one shot, coloured by its outcome; the cross is the current shot. Click a cell to load its shot (one undo step).</source>
        <translation>Minden cella egy ütés, az eredménye szerint színezve; a kereszt az aktuális ütés. Egy cellára kattintva betölti az ütését (egy visszavonási lépés).</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Mégse</translation>
    </message>
    <message>
        <source>Stop the running analysis (Esc)</source>
        <translation>A futó elemzés leállítása (Esc)</translation>
    </message>
    <message>
        <source>Goal</source>
        <translation>Cél</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Megszakítva.</translation>
    </message>
    <message>
        <source>The setup has no cue strike to scan.</source>
        <translation>A felállásban nincs letapogatható dákóütés.</translation>
    </message>
    <message>
        <source>scanning…</source>
        <translation>letapogatás…</translation>
    </message>
    <message>
        <source>Scanning the tolerance of %1 parameters for: %2</source>
        <translation>%1 paraméter tűrésének letapogatása ehhez: %2</translation>
    </message>
    <message>
        <source>The setup has no cue strike: no tip offsets to map.</source>
        <translation>A felállásban nincs dákóütés: nincs feltérképezhető dákóvég-eltolás.</translation>
    </message>
    <message>
        <source>Choose two keys of this setup.</source>
        <translation>Válasszon két kulcsot ebből a felállásból.</translation>
    </message>
    <message>
        <source>Choose two different keys.</source>
        <translation>Válasszon két különböző kulcsot.</translation>
    </message>
    <message>
        <source>Mapping %1 shots for: %2</source>
        <translation>%1 ütés feltérképezése ehhez: %2</translation>
    </message>
    <message>
        <source>%1 of %2 simulated shots meet the goal.</source>
        <translation>%2 szimulált ütésből %1 teljesíti a célt.</translation>
    </message>
    <message>
        <source>That tip offset lies beyond the miscue limit.</source>
        <translation>Ez a dákóvég-eltolás a lecsúszási határon túl van.</translation>
    </message>
    <message>
        <source>The setup changed since the map was made; map again.</source>
        <translation>A felállás megváltozott a térkép készítése óta; térképezzen újra.</translation>
    </message>
    <message>
        <source>Load shot from the map (%1 = %2, %3 = %4)</source>
        <translation>Ütés betöltése a térképről (%1 = %2, %3 = %4)</translation>
    </message>
    <message>
        <source>That cell&apos;s shot is not a legal setup.</source>
        <translation>Ennek a cellának az ütése nem szabályos felállás.</translation>
    </message>
    <message>
        <source>the setup changed: scan again</source>
        <translation>a felállás megváltozott: tapogassa le újra</translation>
    </message>
    <message>
        <source>The setup changed: the map was dropped.</source>
        <translation>A felállás megváltozott: a térkép elvetve.</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Irány</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Sebesség</translation>
    </message>
    <message>
        <source>Elevation</source>
        <translation>Emelés</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Oldal</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Magasság</translation>
    </message>
    <message>
        <source>Parameter</source>
        <translation>Paraméter</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Ettől</translation>
    </message>
    <message>
        <source>To</source>
        <translation>Eddig</translation>
    </message>
    <message>
        <source>Width</source>
        <translation>Szélesség</translation>
    </message>
    <message>
        <source>Below</source>
        <translation>Alatta</translation>
    </message>
    <message>
        <source>Above</source>
        <translation>Fölötte</translation>
    </message>
    <message>
        <source>What lies below the window: the goal fails there, or the scan ends (the window may go on)</source>
        <translation>Ami az ablak alatt van: ott a cél nem teljesül, vagy ott ér véget a letapogatás (az ablak folytatódhat)</translation>
    </message>
    <message>
        <source>What lies above the window: the goal fails there, or the scan ends (the window may go on)</source>
        <translation>Ami az ablak fölött van: ott a cél nem teljesül, vagy ott ér véget a letapogatás (az ablak folytatódhat)</translation>
    </message>
    <message>
        <source>Each parameter&apos;s window around the current shot, in its unit (°, m/s, R)</source>
        <translation>Minden paraméter ablaka a mostani ütés körül, a saját egységében (°, m/s, R)</translation>
    </message>
    <message>
        <source>Goal: %1</source>
        <translation>Cél: %1</translation>
    </message>
    <message>
        <source>Scanned %1 parameters, %2 shots simulated.</source>
        <translation>%1 paraméter letapogatva, %2 ütés szimulálva.</translation>
    </message>
    <message>
        <source>none in the scan</source>
        <translation>nincs a letapogatott tartományban</translation>
    </message>
    <message>
        <source>scan&apos;s edge</source>
        <translation>a letapogatás széle</translation>
    </message>
    <message>
        <source>fails</source>
        <translation>nem teljesül</translation>
    </message>
</context>
<context>
    <name>cuelab::BallEditor</name>
    <message>
        <source>The ball&apos;s id: unique, not empty; the shot, the events and the command line name the ball by it</source>
        <translation>A golyó azonosítója: egyedi, nem üres; az ütés, az események és a parancssor ezzel nevezik meg a golyót</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>Position of the centre along the length at t = 0, in metres</source>
        <translation>A középpont helye a hosszúság mentén t = 0-kor, méterben</translation>
    </message>
    <message>
        <source>Position of the centre across the width at t = 0, in metres</source>
        <translation>A középpont helye a szélesség mentén t = 0-kor, méterben</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>Velocity along the length at t = 0, in m/s (before any cue strike)</source>
        <translation>Sebesség a hosszúság mentén t = 0-kor, m/s-ban (minden dákóütés előtt)</translation>
    </message>
    <message>
        <source>Velocity across the width at t = 0, in m/s (before any cue strike)</source>
        <translation>Sebesség a szélesség mentén t = 0-kor, m/s-ban (minden dákóütés előtt)</translation>
    </message>
    <message>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <source>Angular velocity about the length axis x at t = 0, in rad/s</source>
        <translation>Szögsebesség a hossztengely (x) körül t = 0-kor, rad/s-ban</translation>
    </message>
    <message>
        <source>Angular velocity about the width axis y at t = 0, in rad/s (rolling along +x: wy = vx / R)</source>
        <translation>Szögsebesség a keresztirányú tengely (y) körül t = 0-kor, rad/s-ban (gördülés +x irányban: wy = vx / R)</translation>
    </message>
    <message>
        <source>Angular velocity about the vertical axis z at t = 0, in rad/s (side spin)</source>
        <translation>Szögsebesség a függőleges tengely (z) körül t = 0-kor, rad/s-ban (oldalpörgetés)</translation>
    </message>
    <message>
        <source>Radius of the ball in metres (pool 0.028575 m, snooker 0.02625 m, carom 0.03075 m)</source>
        <translation>A golyó sugara méterben (pool 0,028575 m, snooker 0,02625 m, karambol 0,03075 m)</translation>
    </message>
    <message>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <source>Mass of the ball in kg (pool 0.170 kg, snooker 0.140 kg, carom 0.210 kg)</source>
        <translation>A golyó tömege kg-ban (pool 0,170 kg, snooker 0,140 kg, karambol 0,210 kg)</translation>
    </message>
    <message>
        <source>&amp;Id</source>
        <translation>&amp;Azonosító</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Hely</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Sebesség</translation>
    </message>
    <message>
        <source>Spin</source>
        <translation>Pörgetés</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Sugár</translation>
    </message>
    <message>
        <source>Mass</source>
        <translation>Tömeg</translation>
    </message>
    <message>
        <source>Ball %1 at t = 0</source>
        <translation>%1 golyó t = 0-kor</translation>
    </message>
    <message>
        <source>No ball selected</source>
        <translation>Nincs kijelölt golyó</translation>
    </message>
    <message>
        <source>Rename ball %1 to %2</source>
        <translation>A(z) %1 golyó átnevezése erre: %2</translation>
    </message>
</context>
<context>
    <name>cuelab::BallsPanel</name>
    <message>
        <source>Ball</source>
        <translation>Golyó</translation>
    </message>
    <message>
        <source>x₀ (m)</source>
        <translation>x₀ (m)</translation>
    </message>
    <message>
        <source>y₀ (m)</source>
        <translation>y₀ (m)</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Állapot</translation>
    </message>
    <message>
        <source>Position (m)</source>
        <translation>Hely (m)</translation>
    </message>
    <message>
        <source>|v| (m/s)</source>
        <translation>|v| (m/s)</translation>
    </message>
    <message>
        <source>Set-up position along the length, in metres (double-click to edit)</source>
        <translation>Kiinduló hely az asztal hossza mentén, méterben (dupla kattintással szerkeszthető)</translation>
    </message>
    <message>
        <source>Set-up position across the width, in metres (double-click to edit)</source>
        <translation>Kiinduló hely az asztal szélessége mentén, méterben (dupla kattintással szerkeszthető)</translation>
    </message>
    <message>
        <source>Motion state at the current time</source>
        <translation>Mozgásállapot az aktuális időpontban</translation>
    </message>
    <message>
        <source>Position at the current time, in metres</source>
        <translation>Hely az aktuális időpontban, méterben</translation>
    </message>
    <message>
        <source>Speed at the current time, in m/s</source>
        <translation>Sebesség az aktuális időpontban, m/s-ban</translation>
    </message>
    <message>
        <source>&amp;Add Ball</source>
        <translation>Golyó &amp;hozzáadása</translation>
    </message>
    <message>
        <source>Add a ball on a free spot near the centre of the table</source>
        <translation>Golyó hozzáadása egy szabad helyre az asztal közepe közelében</translation>
    </message>
    <message>
        <source>&amp;Remove Ball</source>
        <translation>Golyó &amp;eltávolítása</translation>
    </message>
    <message>
        <source>Remove the selected ball</source>
        <translation>A kijelölt golyó eltávolítása</translation>
    </message>
    <message>
        <source>D&amp;uplicate Ball</source>
        <translation>Golyó &amp;megkettőzése</translation>
    </message>
    <message>
        <source>Add a copy of the selected ball next to it</source>
        <translation>A kijelölt golyó másolatának elhelyezése mellé</translation>
    </message>
    <message>
        <source>Rac&amp;k</source>
        <translation>&amp;Gúla</translation>
    </message>
    <message>
        <source>Replace the balls by a standard rack</source>
        <translation>A golyók lecserélése egy szabályos gúlára</translation>
    </message>
    <message>
        <source>Rack</source>
        <translation>Gúla</translation>
    </message>
    <message>
        <source>Ball id (double-click to rename)</source>
        <translation>A golyó azonosítója (dupla kattintással átnevezhető)</translation>
    </message>
    <message>
        <source>Rename ball %1 to %2</source>
        <translation>A(z) %1 golyó átnevezése erre: %2</translation>
    </message>
    <message>
        <source>Move ball %1</source>
        <translation>A(z) %1 golyó áthelyezése</translation>
    </message>
</context>
<context>
    <name>cuelab::CollisionTable</name>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>exact t (s)</source>
        <translation>pontos t (s)</translation>
    </message>
    <message>
        <source>exact</source>
        <translation>pontos</translation>
    </message>
    <message>
        <source>engine t (s)</source>
        <translation>motor t (s)</translation>
    </message>
    <message>
        <source>engine</source>
        <translation>motor</translation>
    </message>
    <message>
        <source>Δt (ms)</source>
        <translation>Δt (ms)</translation>
    </message>
    <message>
        <source>The collisions each method found, in order; # is the exact run&apos;s event number, as in the Events list. Δt is the engine&apos;s time minus the exact one, in milliseconds, while the two sequences agree; the first row where they differ is marked. Double-click a row to go to its time.</source>
        <translation>Az egyes módszerek által talált ütközések, sorrendben; a # a pontos futás eseményszáma, ahogy az Események listában. Δt a motor időpontja mínusz a pontos, milliszekundumban, amíg a két sorozat egyezik; az első eltérő sor meg van jelölve. Dupla kattintással a sor időpontjára ugrik.</translation>
    </message>
    <message>
        <source>%1 t (s)</source>
        <translation>%1 t (s)</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(nincs)</translation>
    </message>
    <message>
        <source>The first collision where the two methods disagree</source>
        <translation>Az első ütközés, amelyben a két módszer eltér</translation>
    </message>
</context>
<context>
    <name>cuelab::CompareChart</name>
    <message>
        <source>Position error against the exact run</source>
        <translation>Helyzeti eltérés a pontos futáshoz képest</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>idő (s)</translation>
    </message>
    <message>
        <source>error (mm)</source>
        <translation>eltérés (mm)</translation>
    </message>
    <message>
        <source>now</source>
        <translation>most</translation>
    </message>
    <message>
        <source>How far each ball of the chosen engine is from the same ball in the exact simulation, in millimetres (metres when it passes a metre), at every sample time; the dashed line is the current time</source>
        <translation>Milyen messze van a választott motor minden golyója ugyanannak a golyónak a pontos szimulációbeli helyétől, milliméterben (méterben, ha meghaladja az egy métert), minden mintavételi időpontban; a szaggatott vonal a jelenlegi idő</translation>
    </message>
    <message>
        <source>error (m)</source>
        <translation>eltérés (m)</translation>
    </message>
</context>
<context>
    <name>cuelab::ComparePanel</name>
    <message>
        <source>The collisions part after the exact run&apos;s last one (%1 of %2 agree; largest time difference %3 ms).</source>
        <translation>Az ütközések a pontos futás utolsó ütközése után válnak el (%2-ból %1 egyezik; a legnagyobb időkülönbség %3 ms).</translation>
    </message>
    <message>
        <source>Ghosts in the table view</source>
        <translation>Szellemek az asztalnézetben</translation>
    </message>
    <message>
        <source>Discrete: the 2011 method (NeHe 30)</source>
        <translation>Diszkrét: a 2011-es módszer (NeHe 30)</translation>
    </message>
    <message>
        <source>Box2D 2.4</source>
        <translation>Box2D 2.4</translation>
    </message>
    <message>
        <source>Exact (itself)</source>
        <translation>Pontos (önmaga)</translation>
    </message>
    <message>
        <source>The method to run the shot with and measure against the exact simulation</source>
        <translation>A módszer, amellyel az ütés fut, és amelyet a pontos szimulációval összemér</translation>
    </message>
    <message>
        <source> ms</source>
        <translation> ms</translation>
    </message>
    <message>
        <source>The engine&apos;s fixed time step, in milliseconds (16.667 ms = 60 Hz, a game frame)</source>
        <translation>A motor rögzített időlépése milliszekundumban (16,667 ms = 60 Hz, egy játékképkocka)</translation>
    </message>
    <message>
        <source>Draw the engine&apos;s balls and paths as translucent ghosts beside the exact ones</source>
        <translation>A motor golyóinak és pályáinak kirajzolása áttetsző szellemként a pontosak mellett</translation>
    </message>
    <message>
        <source>The engine is running in the background</source>
        <translation>A motor a háttérben fut</translation>
    </message>
    <message>
        <source>What of this shot the engine cannot represent: it runs without it</source>
        <translation>Amit ebből az ütésből a motor nem tud ábrázolni: nélküle fut</translation>
    </message>
    <message>
        <source>Engine</source>
        <translation>Motor</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Lépés</translation>
    </message>
    <message>
        <source>Position error</source>
        <translation>Helyzeti eltérés</translation>
    </message>
    <message>
        <source>Collisions</source>
        <translation>Ütközések</translation>
    </message>
    <message>
        <source>Open a shot to compare.</source>
        <translation>Nyisson meg egy ütést az összehasonlításhoz.</translation>
    </message>
    <message>
        <source>The engine&apos;s fixed time step, in milliseconds (16.667 ms = 60 Hz, a game frame); at least %1 ms: %2</source>
        <translation>A motor rögzített időlépése milliszekundumban (16,667 ms = 60 Hz, egy játékképkocka); legalább %1 ms: %2</translation>
    </message>
    <message>
        <source>Velocity iterations</source>
        <translation>Sebességiterációk</translation>
    </message>
    <message>
        <source>Box2D&apos;s velocity iterations per step (8 recommended)</source>
        <translation>A Box2D sebességiterációi lépésenként (8 ajánlott)</translation>
    </message>
    <message>
        <source>Sub-steps</source>
        <translation>Részlépések</translation>
    </message>
    <message>
        <source>Sphere tests per step of the 2011 method: a hit between two tests can be missed</source>
        <translation>Gömbvizsgálatok lépésenként a 2011-es módszerben: két vizsgálat közötti találat kimaradhat</translation>
    </message>
    <message>
        <source>Running %1…</source>
        <translation>%1 fut…</translation>
    </message>
    <message>
        <source>Largest error %1 (ball %2 at %3 s).</source>
        <translation>A legnagyobb eltérés %1 (%2 golyó, %3 s-nál).</translation>
    </message>
    <message>
        <source>No position error.</source>
        <translation>Nincs helyzeti eltérés.</translation>
    </message>
    <message>
        <source>At rest, ball %1 lies %2 from where the exact run leaves it.</source>
        <translation>Nyugalomban a(z) %1 golyó %2 távolságra van attól a helytől, ahol a pontos futás hagyja.</translation>
    </message>
    <message>
        <source>The collisions part at event %1 (%2 of %3 agree; largest time difference %4 ms).</source>
        <translation>Az ütközések a(z) %1 eseménynél válnak el (%3-ból %2 egyezik; a legnagyobb időkülönbség %4 ms).</translation>
    </message>
    <message>
        <source>Same %1 collisions in the same order (largest time difference %2 ms).</source>
        <translation>Ugyanaz a(z) %1 ütközés ugyanabban a sorrendben (a legnagyobb időkülönbség %2 ms).</translation>
    </message>
    <message>
        <source>Deepest overlap of two balls: %1.</source>
        <translation>Két golyó legmélyebb átfedése: %1.</translation>
    </message>
    <message>
        <source>&lt;i&gt;The exact engine represents every feature.&lt;/i&gt;</source>
        <translation>&lt;i&gt;A pontos motor minden jellemzőt ábrázol.&lt;/i&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1 cannot represent:&lt;/b&gt;&lt;ul style=&quot;margin-left: 12px; -qt-list-indent: 0;&quot;&gt;</source>
        <translation>&lt;b&gt;Amit a(z) %1 nem tud ábrázolni:&lt;/b&gt;&lt;ul style=&quot;margin-left: 12px; -qt-list-indent: 0;&quot;&gt;</translation>
    </message>
    <message>
        <source>Cannot compare: %1</source>
        <translation>Az összehasonlítás nem lehetséges: %1</translation>
    </message>
</context>
<context>
    <name>cuelab::ConservationWidget</name>
    <message>
        <source>Left: each ball&apos;s momentum m·v (N s) drawn tip to tail, before and after, with their total (dashed). Right: kinetic energy (J) before and after, translation (solid) and rotation (light).</source>
        <translation>Balra: minden golyó m·v lendülete (N s) egymás után fűzve, előtte és utána, az összegükkel (szaggatott). Jobbra: a mozgási energia (J) előtte és utána, haladó (telt) és forgó (halvány).</translation>
    </message>
    <message>
        <source>Momenta and energy of the selected event</source>
        <translation>A kijelölt esemény lendületei és energiája</translation>
    </message>
    <message>
        <source>Momentum (N s)</source>
        <translation>Lendület (N s)</translation>
    </message>
    <message>
        <source>before</source>
        <translation>előtte</translation>
    </message>
    <message>
        <source>after</source>
        <translation>utána</translation>
    </message>
    <message>
        <source>J (cushion)</source>
        <translation>J (mantinel)</translation>
    </message>
    <message>
        <source>Energy (J)</source>
        <translation>Energia (J)</translation>
    </message>
    <message>
        <source>ΔE = %1 J (%2 %)</source>
        <translation>ΔE = %1 J (%2 %)</translation>
    </message>
    <message>
        <source>ΔE = %1 J</source>
        <translation>ΔE = %1 J</translation>
    </message>
    <message>
        <source>ΔE = 0 J (conserved)</source>
        <translation>ΔE = 0 J (megmarad)</translation>
    </message>
    <message>
        <source>total</source>
        <translation>összesen</translation>
    </message>
    <message>
        <source>light: rotation</source>
        <translation>világos: forgás</translation>
    </message>
</context>
<context>
    <name>cuelab::CushionModelParameters</name>
    <message>
        <source>Cost grows in proportion: about 0.1 ms of computing per cushion hit at 1000 steps, about 0.1 s at 1000000, in every shot of a sweep or an Analysis map too.</source>
        <translation>A költség arányosan nő: 1000 lépésnél párnaütközésenként kb. 0,1 ms számítás, 1000000-nál kb. 0,1 s, egy söprés vagy elemzési térkép minden lövésében is.</translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>%1 módosítása</translation>
    </message>
</context>
<context>
    <name>cuelab::DisplayNames</name>
    <message>
        <source>stationary</source>
        <translation>áll</translation>
    </message>
    <message>
        <source>spinning</source>
        <translation>helyben pörög</translation>
    </message>
    <message>
        <source>sliding</source>
        <translation>csúszik</translation>
    </message>
    <message>
        <source>rolling</source>
        <translation>gördül</translation>
    </message>
    <message>
        <source>pocketed</source>
        <translation>lyukban</translation>
    </message>
    <message>
        <source>cue-strike</source>
        <translation>dákóütés</translation>
    </message>
    <message>
        <source>ball-ball</source>
        <translation>golyó–golyó</translation>
    </message>
    <message>
        <source>ball-cushion</source>
        <translation>golyó–mantinel</translation>
    </message>
    <message>
        <source>ball-pocket</source>
        <translation>lyukba esés</translation>
    </message>
    <message>
        <source>slide-to-roll</source>
        <translation>csúszásból gördülés</translation>
    </message>
    <message>
        <source>slide-to-spin</source>
        <translation>csúszásból helyben pörgés</translation>
    </message>
    <message>
        <source>slide-to-stop</source>
        <translation>csúszásból megállás</translation>
    </message>
    <message>
        <source>roll-to-spin</source>
        <translation>gördülésből helyben pörgés</translation>
    </message>
    <message>
        <source>roll-to-stop</source>
        <translation>gördülésből megállás</translation>
    </message>
    <message>
        <source>spin-to-stop</source>
        <translation>pörgésből megállás</translation>
    </message>
</context>
<context>
    <name>cuelab::Document</name>
    <message>
        <source>Untitled</source>
        <translation>Névtelen</translation>
    </message>
    <message>
        <source>Move ball %1</source>
        <translation>A(z) %1 golyó áthelyezése</translation>
    </message>
    <message>
        <source>There is no free place on the table for another ball.</source>
        <translation>Nincs szabad hely az asztalon még egy golyónak.</translation>
    </message>
    <message>
        <source>Add ball %1</source>
        <translation>A(z) %1 golyó hozzáadása</translation>
    </message>
    <message>
        <source>Remove ball %1</source>
        <translation>A(z) %1 golyó eltávolítása</translation>
    </message>
    <message>
        <source>Duplicate ball %1</source>
        <translation>A(z) %1 golyó megkettőzése</translation>
    </message>
    <message>
        <source>Rack: %1</source>
        <translation>Gúla: %1</translation>
    </message>
    <message>
        <source>Clear the table</source>
        <translation>Az asztal kiürítése</translation>
    </message>
    <message>
        <source>Place ball %1</source>
        <translation>A(z) %1 golyó elhelyezése</translation>
    </message>
    <message>
        <source>Aim at the rack</source>
        <translation>Célzás a gúlára</translation>
    </message>
    <message>
        <source>Reset physics to defaults</source>
        <translation>A fizika visszaállítása az alapértékekre</translation>
    </message>
    <message>
        <source>untitled</source>
        <translation>névtelen</translation>
    </message>
    <message>
        <source>Set the velocity of ball %1</source>
        <translation>A(z) %1 golyó sebességének beállítása</translation>
    </message>
    <message>
        <source>There is no free place on the new table for ball &quot;%1&quot;.</source>
        <translation>Az új asztalon nincs szabad hely a(z) „%1” golyónak.</translation>
    </message>
    <message numerus="yes">
        <source>%1, moving %n ball(s): %2</source>
        <translation>
            <numerusform>%1, %n golyó áthelyezésével: %2</numerusform>
        </translation>
    </message>
    <message>
        <source>Rename the lesson</source>
        <translation>A lecke átnevezése</translation>
    </message>
    <message>
        <source>Edit the lesson&apos;s notes</source>
        <translation>A lecke megjegyzéseinek szerkesztése</translation>
    </message>
</context>
<context>
    <name>cuelab::EventTableModel</name>
    <message>
        <source>Time (s)</source>
        <translation>Idő (s)</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Fajta</translation>
    </message>
    <message>
        <source>Agents</source>
        <translation>Résztvevők</translation>
    </message>
    <message>
        <source>Δt (s)</source>
        <translation>Δt (s)</translation>
    </message>
    <message>
        <source>Key values</source>
        <translation>Fő értékek</translation>
    </message>
    <message>
        <source>Time of the event in seconds after the strike (exact: a root of a polynomial)</source>
        <translation>Az esemény időpontja az ütés után, másodpercben (pontos: egy polinom gyöke)</translation>
    </message>
    <message>
        <source>Seconds since the previous event</source>
        <translation>Az előző esemény óta eltelt másodpercek</translation>
    </message>
    <message>
        <source>Collisions: normal approach speed (m/s) and impulse (N·s); changes of motion: speed after (m/s)</source>
        <translation>Ütközések: normális irányú közeledési sebesség (m/s) és erőlökés (N·s); mozgásváltások: az utána mért sebesség (m/s)</translation>
    </message>
</context>
<context>
    <name>cuelab::EventTreeModel</name>
    <message numerus="yes">
        <source>%n ball(s): %1</source>
        <translation>
            <numerusform>%n golyó: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n events at one instant</source>
        <translation>
            <numerusform>%n esemény egy pillanatban</numerusform>
        </translation>
    </message>
    <message>
        <source>, fastest v_rel %1</source>
        <translation>, leggyorsabb v_rel %1</translation>
    </message>
    <message numerus="yes">
        <source>%n events at the same instant (expand to see each)</source>
        <translation>
            <numerusform>%n esemény ugyanabban a pillanatban (nyissa ki, hogy mindet lássa)</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cuelab::EventsPanel</name>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>Hide collisions whose normal approach speed is below this, in m/s (0 = show every collision)</source>
        <translation>Az ennél kisebb normális irányú közeledési sebességű ütközések elrejtése, m/s-ban (0 = minden ütközés látszik)</translation>
    </message>
    <message>
        <source>All events</source>
        <translation>Minden esemény</translation>
    </message>
    <message>
        <source>No changes of motion</source>
        <translation>Mozgásváltások nélkül</translation>
    </message>
    <message>
        <source>Collisions</source>
        <translation>Ütközések</translation>
    </message>
    <message>
        <source>Ball–ball</source>
        <translation>Golyó–golyó</translation>
    </message>
    <message>
        <source>Cushions and jaws</source>
        <translation>Mantinelek és lyukpofák</translation>
    </message>
    <message>
        <source>Pockets</source>
        <translation>Lyukak</translation>
    </message>
    <message>
        <source>Cue strikes</source>
        <translation>Dákóütések</translation>
    </message>
    <message>
        <source>Changes of motion</source>
        <translation>Mozgásváltások</translation>
    </message>
    <message>
        <source>Which kinds of event to list: changes of motion are slide to roll, roll to stop, ...; a break has many more of them than collisions</source>
        <translation>Milyen fajta eseményeket listázzon: mozgásváltás a csúszásból gördülés, a gördülésből megállás, …; egy kezdőlökésben sokkal több van belőlük, mint ütközésből</translation>
    </message>
    <message>
        <source>List only the events this ball takes part in</source>
        <translation>Csak azoknak az eseményeknek a listázása, amelyekben ez a golyó részt vesz</translation>
    </message>
    <message>
        <source>any speed</source>
        <translation>bármilyen sebesség</translation>
    </message>
    <message>
        <source>Select an event to jump to its time and see it in the Inspector; a row of events at one instant expands</source>
        <translation>Válasszon ki egy eseményt: a lejátszás az időpontjára ugrik, és a Vizsgáló megmutatja; az egy pillanatban történt események sora kinyitható</translation>
    </message>
    <message>
        <source>v_rel</source>
        <translation>v_rel</translation>
    </message>
    <message>
        <source>Every ball</source>
        <translation>Minden golyó</translation>
    </message>
    <message>
        <source>Ball %1</source>
        <translation>%1 golyó</translation>
    </message>
</context>
<context>
    <name>cuelab::ExplainPanel</name>
    <message>
        <source>Select an event (in Events, or step to one with Shift+Right) to see its mathematics.</source>
        <translation>Válasszon ki egy eseményt (az Események panelen, vagy lépjen rá Shift+Jobbra nyíllal), hogy lássa a matematikáját.</translation>
    </message>
    <message>
        <source>The time-of-impact polynomial f(τ) over the prediction window: its roots are marked, the root that gave the event in red. τ in seconds from t₀.</source>
        <translation>Az ütközési idő f(τ) polinomja az előrejelzési ablakban: a gyökei megjelölve, az eseményt adó gyök pirossal. τ másodpercben, t₀-tól.</translation>
    </message>
</context>
<context>
    <name>cuelab::FirstStartTip</name>
    <message>
        <source>Hide this tip (Help › Show First-Start Tip brings it back)</source>
        <translation>A tipp elrejtése (a Súgó › Kezdő tipp megjelenítése visszahozza)</translation>
    </message>
    <message>
        <source>&lt;b&gt;New to CueLab?&lt;/b&gt; Open a lesson from &lt;i&gt;File › Examples&lt;/i&gt;. &lt;b&gt;Space&lt;/b&gt; plays the shot, &lt;b&gt;←/→&lt;/b&gt; step a frame, &lt;b&gt;Shift+←/→&lt;/b&gt; jump to the next event; click an event in &lt;i&gt;Events&lt;/i&gt; to read its mathematics. Drag a ball to move it; every edit can be undone (&lt;b&gt;Ctrl+Z&lt;/b&gt;). &lt;b&gt;F1&lt;/b&gt; opens the user guide; &lt;i&gt;Help › Keyboard and Mouse&lt;/i&gt; lists every shortcut and mouse gesture.</source>
        <translation>&lt;b&gt;Először használja a CueLabot?&lt;/b&gt; Nyisson meg egy leckét a &lt;i&gt;Fájl › Példák&lt;/i&gt; menüből. A &lt;b&gt;Szóköz&lt;/b&gt; lejátssza az ütést, a &lt;b&gt;←/→&lt;/b&gt; egy képkockát lép, a &lt;b&gt;Shift+←/→&lt;/b&gt; a következő eseményre ugrik; kattintson egy eseményre az &lt;i&gt;Események&lt;/i&gt; panelen, hogy elolvassa a matematikáját. Egy golyót húzással helyezhet át; minden szerkesztés visszavonható (&lt;b&gt;Ctrl+Z&lt;/b&gt;). Az &lt;b&gt;F1&lt;/b&gt; megnyitja a felhasználói útmutatót; a &lt;i&gt;Súgó › Billentyűzet és egér&lt;/i&gt; felsorol minden billentyűparancsot és egérmozdulatot.</translation>
    </message>
</context>
<context>
    <name>cuelab::InspectorPanel</name>
    <message>
        <source>Quantity</source>
        <translation>Mennyiség</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Érték</translation>
    </message>
    <message>
        <source>Select a ball or an event</source>
        <translation>Válasszon ki egy golyót vagy egy eseményt</translation>
    </message>
    <message>
        <source>State</source>
        <translation>Állapot</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Hely</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Sebességvektor</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Sebesség</translation>
    </message>
    <message>
        <source>Spin</source>
        <translation>Pörgetés</translation>
    </message>
    <message>
        <source>Angular velocity (ωx, ωy, ωz); ωz &gt; 0 is counter-clockwise seen from above</source>
        <translation>Szögsebesség (ωx, ωy, ωz); ωz &gt; 0 felülről nézve az óramutató járásával ellentétes</translation>
    </message>
    <message>
        <source>Slip</source>
        <translation>Csúszás</translation>
    </message>
    <message>
        <source>Velocity of the contact point with the cloth, v + R (z × ω); zero when rolling</source>
        <translation>A posztóval érintkező pont sebessége, v + R (z × ω); gördüléskor nulla</translation>
    </message>
    <message>
        <source>Ball %1</source>
        <translation>%1 golyó</translation>
    </message>
    <message>
        <source>at t = %1</source>
        <translation>t = %1 időpontban</translation>
    </message>
    <message>
        <source>Pocket</source>
        <translation>Lyuk</translation>
    </message>
    <message>
        <source>Momentum</source>
        <translation>Lendület</translation>
    </message>
    <message>
        <source>Kinetic energy</source>
        <translation>Mozgási energia</translation>
    </message>
    <message>
        <source>Translation plus rotation, I = 2/5 m R²</source>
        <translation>Haladó és forgó mozgás együtt, I = 2/5 m R²</translation>
    </message>
    <message>
        <source>Radius</source>
        <translation>Sugár</translation>
    </message>
    <message>
        <source>Mass</source>
        <translation>Tömeg</translation>
    </message>
    <message>
        <source>Event %1</source>
        <translation>%1. esemény</translation>
    </message>
    <message>
        <source>Agents</source>
        <translation>Résztvevők</translation>
    </message>
    <message>
        <source>Time of impact</source>
        <translation>Az ütközés időpontja</translation>
    </message>
    <message>
        <source>Exact time of the event: a root of the polynomial that describes the contact</source>
        <translation>Az esemény pontos időpontja: az érintkezést leíró polinom egy gyöke</translation>
    </message>
    <message>
        <source>Since previous</source>
        <translation>Az előző óta</translation>
    </message>
    <message>
        <source>Contact point</source>
        <translation>Érintkezési pont</translation>
    </message>
    <message>
        <source>Contact normal</source>
        <translation>Érintkezési normális</translation>
    </message>
    <message>
        <source>Unit normal from the first ball towards the other body</source>
        <translation>Egységnyi normálvektor az első golyótól a másik test felé</translation>
    </message>
    <message>
        <source>Relative speed</source>
        <translation>Relatív sebesség</translation>
    </message>
    <message>
        <source>Normal approach speed just before contact</source>
        <translation>Normális irányú közeledési sebesség közvetlenül az érintkezés előtt</translation>
    </message>
    <message>
        <source>Impulse</source>
        <translation>Erőlökés</translation>
    </message>
    <message>
        <source>Impulse on the first ball, table frame</source>
        <translation>Az első golyót érő erőlökés, az asztal koordináta-rendszerében</translation>
    </message>
    <message>
        <source>|Impulse|</source>
        <translation>|Erőlökés|</translation>
    </message>
    <message>
        <source>Before</source>
        <translation>Előtte</translation>
    </message>
    <message>
        <source>After</source>
        <translation>Utána</translation>
    </message>
    <message>
        <source>Both balls</source>
        <translation>Mindkét golyó</translation>
    </message>
    <message>
        <source>Totals</source>
        <translation>Összesen</translation>
    </message>
    <message>
        <source>Momentum before</source>
        <translation>Lendület előtte</translation>
    </message>
    <message>
        <source>Momentum after</source>
        <translation>Lendület utána</translation>
    </message>
    <message>
        <source>Kinetic energy before</source>
        <translation>Mozgási energia előtte</translation>
    </message>
    <message>
        <source>Kinetic energy after</source>
        <translation>Mozgási energia utána</translation>
    </message>
    <message>
        <source>Energy change</source>
        <translation>Energiaváltozás</translation>
    </message>
</context>
<context>
    <name>cuelab::LessonPanel</name>
    <message>
        <source>Name of the shot</source>
        <translation>Az ütés neve</translation>
    </message>
    <message>
        <source>The setup&apos;s name (saved in the file as &quot;name&quot;)</source>
        <translation>A felállás neve (a fájlban &quot;name&quot; néven mentve)</translation>
    </message>
    <message>
        <source>What this shot teaches: write the lesson here.</source>
        <translation>Mit tanít ez az ütés: ide írja a leckét.</translation>
    </message>
    <message>
        <source>The setup&apos;s notes (saved in the file as &quot;notes&quot;); each finished edit is one undo step</source>
        <translation>A felállás megjegyzései (a fájlban &quot;notes&quot; néven mentve); minden befejezett szerkesztés egy visszavonási lépés</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Név</translation>
    </message>
    <message>
        <source>The notes describe the shot as it was when they were written. Undo the changes, or edit the notes to match the shot (that clears this flag). The lesson report prints the same warning.</source>
        <translation>A jegyzetek az ütést az írásuk idején érvényes állapotában írják le. Vonja vissza a változtatásokat, vagy igazítsa a jegyzeteket az ütéshez (ez eltünteti ezt a jelzést). A leckejelentés ugyanezt a figyelmeztetést nyomtatja.</translation>
    </message>
    <message>
        <source>These notes were written for the shot before these changes:
• %1</source>
        <translation>Ezek a jegyzetek az ütés alábbi változtatások előtti állapotához készültek:
• %1</translation>
    </message>
</context>
<context>
    <name>cuelab::MainWindow</name>
    <message>
        <source>%1. Beyond real play: %2</source>
        <translation>%1. A valódi játékon túli értékek: %2</translation>
    </message>
    <message>
        <source>Set the velocity of ball %1</source>
        <translation>A(z) %1 golyó sebességének beállítása</translation>
    </message>
    <message>
        <source>Not applied: %1</source>
        <translation>Nem alkalmazva: %1</translation>
    </message>
    <message>
        <source>%1 fps</source>
        <translation>%1 kép/s</translation>
    </message>
    <message>
        <source>Balls</source>
        <translation>Golyók</translation>
    </message>
    <message>
        <source>Shot</source>
        <translation>Ütés</translation>
    </message>
    <message>
        <source>Physics</source>
        <translation>Fizika</translation>
    </message>
    <message>
        <source>Events</source>
        <translation>Események</translation>
    </message>
    <message>
        <source>Inspector</source>
        <translation>Vizsgáló</translation>
    </message>
    <message>
        <source>&amp;Export</source>
        <translation>&amp;Exportálás</translation>
    </message>
    <message>
        <source>Frames per second the table view draws</source>
        <translation>Az asztal nézetének másodpercenként kirajzolt képkockái</translation>
    </message>
    <message>
        <source>Simulating the edited setup</source>
        <translation>A szerkesztett felállás szimulálása</translation>
    </message>
    <message numerus="yes">
        <source>%n event(s), at rest at %1</source>
        <translation>
            <numerusform>%n esemény, nyugalomban: %1</numerusform>
        </translation>
    </message>
    <message numerus="yes">
        <source>%n event(s), stopped at the time limit</source>
        <translation>
            <numerusform>%n esemény, az időkorlátnál leállítva</numerusform>
        </translation>
    </message>
    <message>
        <source>Cut short: %1</source>
        <translation>Idő előtt leállt: %1</translation>
    </message>
    <message>
        <source>Unsaved Changes</source>
        <translation>Mentetlen változások</translation>
    </message>
    <message>
        <source>%1 has unsaved changes. Save them first?</source>
        <translation>A(z) %1 mentetlen változásokat tartalmaz. Menti őket előbb?</translation>
    </message>
    <message>
        <source>Open Setup</source>
        <translation>Felállás megnyitása</translation>
    </message>
    <message>
        <source>Cannot Open Setup</source>
        <translation>A felállás nem nyitható meg</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Megnyitva: %1</translation>
    </message>
    <message>
        <source>Cannot Open Example</source>
        <translation>A példa nem nyitható meg</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>Example %1: save it to keep your changes</source>
        <translation>%1 példa: mentse el, hogy megmaradjanak a változtatásai</translation>
    </message>
    <message>
        <source>Save Setup As</source>
        <translation>Felállás mentése másként</translation>
    </message>
    <message>
        <source>Cannot Save Setup</source>
        <translation>A felállás nem menthető</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Mentve: %1</translation>
    </message>
    <message>
        <source>%1[*] — CueLab</source>
        <translation>%1[*] — CueLab</translation>
    </message>
    <message>
        <source>About CueLab</source>
        <translation>A CueLab névjegye</translation>
    </message>
    <message>
        <source>&lt;h3&gt;CueLab %1&lt;/h3&gt;&lt;p&gt;An exact, event-based billiards simulator and shot editor: every time of impact is a root of a polynomial.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;CueLab %1&lt;/h3&gt;&lt;p&gt;Pontos, eseményalapú biliárdszimulátor és ütésszerkesztő: minden ütközés időpontja egy polinom gyöke.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fájl</translation>
    </message>
    <message>
        <source>&amp;New</source>
        <translation>Ú&amp;j</translation>
    </message>
    <message>
        <source>A new setup: a 9-ft table with a cue ball and one object ball</source>
        <translation>Új felállás: 9 láb hosszú asztal egy fehér golyóval és egy célgolyóval</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>&amp;Megnyitás…</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>&amp;Legutóbbiak megnyitása</translation>
    </message>
    <message>
        <source>&amp;Examples</source>
        <translation>&amp;Példák</translation>
    </message>
    <message>
        <source>Open the bundled example %1 as a new, untitled setup</source>
        <translation>A mellékelt %1 példa megnyitása új, névtelen felállásként</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>Menté&amp;s</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>Mentés má&amp;sként…</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Kilépés</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>S&amp;zerkesztés</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Visszavonás</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Mégis</translation>
    </message>
    <message>
        <source>Reset &amp;Physics to Defaults</source>
        <translation>A &amp;fizika alapértékeinek visszaállítása</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Nézet</translation>
    </message>
    <message>
        <source>&amp;Panels</source>
        <translation>&amp;Panelek</translation>
    </message>
    <message>
        <source>&amp;Overlays</source>
        <translation>&amp;Rétegek</translation>
    </message>
    <message>
        <source>&amp;Camera</source>
        <translation>&amp;Kamera</translation>
    </message>
    <message>
        <source>&amp;Top</source>
        <translation>&amp;Felülről</translation>
    </message>
    <message>
        <source>&amp;Player</source>
        <translation>&amp;Játékos</translation>
    </message>
    <message>
        <source>&amp;Side</source>
        <translation>&amp;Oldalról</translation>
    </message>
    <message>
        <source>&amp;All Balls</source>
        <translation>&amp;Minden golyó</translation>
    </message>
    <message>
        <source>&amp;Selected Ball Only</source>
        <translation>Csak a &amp;kijelölt golyó</translation>
    </message>
    <message>
        <source>&amp;None</source>
        <translation>&amp;Egyik sem</translation>
    </message>
    <message>
        <source>Pat&amp;hs Of</source>
        <translation>&amp;Pályák mutatása</translation>
    </message>
    <message>
        <source>&amp;Labels Of</source>
        <translation>Fel&amp;iratok mutatása</translation>
    </message>
    <message>
        <source>Whose event times are labelled in the view</source>
        <translation>Kiknek az eseményidőpontjai kapnak feliratot a nézetben</translation>
    </message>
    <message>
        <source>F&amp;ollow Selected Ball</source>
        <translation>A kijelölt golyó &amp;követése</translation>
    </message>
    <message>
        <source>Keep the selected ball at the centre of the view as time runs</source>
        <translation>A kijelölt golyó a nézet közepén marad, ahogy telik az idő</translation>
    </message>
    <message>
        <source>&amp;Zoom to Selection</source>
        <translation>&amp;Nagyítás a kijelölésre</translation>
    </message>
    <message>
        <source>Frame the selected ball&apos;s whole path (the table when no ball is selected)</source>
        <translation>A kijelölt golyó teljes pályájának bekeretezése (kijelölt golyó nélkül az asztalé)</translation>
    </message>
    <message>
        <source>&amp;Full Screen</source>
        <translation>&amp;Teljes képernyő</translation>
    </message>
    <message>
        <source>&amp;Analysis</source>
        <translation>&amp;Elemzés</translation>
    </message>
    <message>
        <source>&amp;Playback</source>
        <translation>&amp;Lejátszás</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Súgó</translation>
    </message>
    <message>
        <source>&amp;Keyboard and Mouse…</source>
        <translation>&amp;Billentyűzet és egér…</translation>
    </message>
    <message>
        <source>Every keyboard shortcut and mouse gesture of the window</source>
        <translation>Az ablak minden billentyűparancsa és egérmozdulata</translation>
    </message>
    <message>
        <source>Show First-Start &amp;Tip</source>
        <translation>Kezdő &amp;tipp megjelenítése</translation>
    </message>
    <message>
        <source>The short tour shown above the table on the first start</source>
        <translation>A rövid bemutató, amely az első indításkor az asztal fölött látszik</translation>
    </message>
    <message>
        <source>&amp;About CueLab</source>
        <translation>A CueLab &amp;névjegye</translation>
    </message>
    <message>
        <source>About &amp;Qt</source>
        <translation>A &amp;Qt névjegye</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>Eredmény</translation>
    </message>
    <message>
        <source>The shot&apos;s outcome: the first ball the struck ball touches, its cushions before that, and the pocketed balls (pocket, time)</source>
        <translation>Az ütés eredménye: az első golyó, amelyet a megütött golyó eltalál, az előtte érintett mantinelek és a lyukba esett golyók (lyuk, időpont)</translation>
    </message>
    <message>
        <source>Plots</source>
        <translation>Grafikonok</translation>
    </message>
    <message>
        <source>Undo History</source>
        <translation>Visszavonási előzmények</translation>
    </message>
    <message>
        <source>A busy shot: the paths and event times of the selected ball %1 only (View › Paths Of, Labels Of)</source>
        <translation>Zsúfolt ütés: csak a kijelölt %1 golyó pályái és eseményidői látszanak (Nézet › Pályák, Feliratok)</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>Visszavonás</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>Újra</translation>
    </message>
    <message>
        <source>La&amp;youts</source>
        <translation>E&amp;lrendezések</translation>
    </message>
    <message>
        <source>Whose paths, trails, event markers and comparison ghosts are drawn (busy shots read better with one ball)</source>
        <translation>Kiknek a pályái, nyomvonalai, eseményjelölői és összehasonlító szellemgolyói látszanak (zsúfolt ütésnél egy golyóval áttekinthetőbb)</translation>
    </message>
    <message>
        <source>CueLab &amp;User Guide</source>
        <translation>A CueLab &amp;felhasználói útmutatója</translation>
    </message>
    <message>
        <source>How to use the window, step by step (the guide bundled with this version)</source>
        <translation>Az ablak használata lépésről lépésre (az ehhez a változathoz mellékelt útmutató)</translation>
    </message>
</context>
<context>
    <name>cuelab::OddsMap</name>
    <message>
        <source>not simulated yet</source>
        <translation>még nincs szimulálva</translation>
    </message>
    <message>
        <source>illegal setup</source>
        <translation>szabálytalan felállás</translation>
    </message>
    <message>
        <source>%1 % (%2–%3 %), %4 of %5 strikes</source>
        <translation>%1% (%2–%3%), %5 ütésből %4</translation>
    </message>
    <message>
        <source>No map of odds yet: choose the axes and press Map odds.</source>
        <translation>Még nincs esélytérkép: válassza ki a tengelyeket, és nyomja meg az Esélytérkép gombot.</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1%</translation>
    </message>
    <message>
        <source>Best (ringed): %1</source>
        <translation>Legjobb (bekarikázva): %1</translation>
    </message>
</context>
<context>
    <name>cuelab::OddsSection</name>
    <message>
        <source>FastFiz defaults</source>
        <translation>A FastFiz alapértékei</translation>
    </message>
    <message>
        <source>Club player</source>
        <translation>Klubjátékos</translation>
    </message>
    <message>
        <source>Professional</source>
        <translation>Profi</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>Egyéni</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Irány</translation>
    </message>
    <message>
        <source>Standard deviation of the aim error, degrees</source>
        <translation>A célzási hiba szórása, fok</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Sebesség</translation>
    </message>
    <message>
        <source>Standard deviation of the cue speed, m/s</source>
        <translation>A dákósebesség szórása, m/s</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Oldal</translation>
    </message>
    <message>
        <source>Standard deviation of the side tip offset, in ball radii (R)</source>
        <translation>Az oldalirányú dákóvég-eltolás szórása, golyósugárban (R)</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Magasság</translation>
    </message>
    <message>
        <source>Standard deviation of the height tip offset, in ball radii (R)</source>
        <translation>A függőleges dákóvég-eltolás szórása, golyósugárban (R)</translation>
    </message>
    <message>
        <source>Elevation</source>
        <translation>Emelés</translation>
    </message>
    <message>
        <source>Standard deviation of the cue elevation, degrees (an error below the cloth is read as above it)</source>
        <translation>A dákó emelésének szórása, fok (a posztó alá mutató hibát a posztó fölöttinek veszi)</translation>
    </message>
    <message>
        <source>Odds under execution noise</source>
        <translation>Esélyek a kivitelezés szórásával</translation>
    </message>
    <message>
        <source>How the player&apos;s strike scatters: normal errors of these standard deviations on every strike parameter (FastFiz&apos;s model). FastFiz&apos;s defaults are those of the computational pool tournaments; the club player and the professional are explained in docs/analysis.md</source>
        <translation>Mennyire szór a játékos ütése: ekkora szórású normális hibák minden ütésparaméteren (a FastFiz modellje). A FastFiz alapértékei a számítógépes pooltornákéi; a klubjátékos és a profi magyarázata a docs/analysis.md-ben</translation>
    </message>
    <message>
        <source>Strikes of the current shot at most; it stops sooner once the 95% interval is within ±1%</source>
        <translation>Legfeljebb ennyi ütés a jelenlegi lövésből; hamarabb megáll, ha a 95%-os intervallum ±1%-on belül van</translation>
    </message>
    <message>
        <source>Odds</source>
        <translation>Esély</translation>
    </message>
    <message>
        <source>Strike the current shot again and again with these errors and count how often it meets the goal</source>
        <translation>A jelenlegi ütés újra és újra, ezekkel a hibákkal, és megszámolja, hányszor teljesül a cél</translation>
    </message>
    <message>
        <source>The share of strikes that meet the goal, and its 95% confidence interval (Wilson)</source>
        <translation>A célt teljesítő ütések aránya és 95%-os konfidenciaintervalluma (Wilson)</translation>
    </message>
    <message>
        <source>The key along the map&apos;s horizontal axis</source>
        <translation>A térkép vízszintes tengelyén változó kulcs</translation>
    </message>
    <message>
        <source>The key along the map&apos;s vertical axis</source>
        <translation>A térkép függőleges tengelyén változó kulcs</translation>
    </message>
    <message>
        <source>First value of the horizontal axis, in the key&apos;s unit</source>
        <translation>A vízszintes tengely első értéke, a kulcs mértékegységében</translation>
    </message>
    <message>
        <source>Last value of the horizontal axis, in the key&apos;s unit</source>
        <translation>A vízszintes tengely utolsó értéke, a kulcs mértékegységében</translation>
    </message>
    <message>
        <source>First value of the vertical axis, in the key&apos;s unit</source>
        <translation>A függőleges tengely első értéke, a kulcs mértékegységében</translation>
    </message>
    <message>
        <source>Last value of the vertical axis, in the key&apos;s unit</source>
        <translation>A függőleges tengely utolsó értéke, a kulcs mértékegységében</translation>
    </message>
    <message>
        <source>Cells along each axis</source>
        <translation>Cellák tengelyenként</translation>
    </message>
    <message>
        <source>Strikes per cell (every cell uses the same errors, so neighbours compare fairly)</source>
        <translation>Ütések cellánként (minden cella ugyanazokat a hibákat kapja, így a szomszédok igazságosan összevethetők)</translation>
    </message>
    <message>
        <source>Map odds</source>
        <translation>Esélytérkép</translation>
    </message>
    <message>
        <source>The odds of every cell of the map; the colours stream in</source>
        <translation>A térkép minden cellájának esélye; a színek folyamatosan érkeznek</translation>
    </message>
    <message>
        <source>Each cell: how often its shot meets the goal under the noise. The ring marks the best cell, the cross the current shot. Click a cell to load its shot (one undo step).</source>
        <translation>Minden cella: a szórás mellett milyen gyakran teljesíti az ütése a célt. A karika a legjobb cellát jelöli, a kereszt a jelenlegi ütést. Egy cellára kattintva betölti az ütését (egy visszavonási lépés).</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Mégse</translation>
    </message>
    <message>
        <source>Stop computing odds</source>
        <translation>Az esélyszámítás leállítása</translation>
    </message>
    <message>
        <source>Player</source>
        <translation>Játékos</translation>
    </message>
    <message>
        <source>Strikes</source>
        <translation>Ütések</translation>
    </message>
    <message>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <source>y</source>
        <translation>y</translation>
    </message>
    <message>
        <source>strikes per cell</source>
        <translation>ütés cellánként</translation>
    </message>
    <message>
        <source>Cells</source>
        <translation>Cellák</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Megszakítva.</translation>
    </message>
    <message>
        <source>The setup has no cue strike: nothing to scatter.</source>
        <translation>A felállásban nincs dákóütés: nincs mit szórni.</translation>
    </message>
    <message>
        <source>Goal: %1</source>
        <translation>Cél: %1</translation>
    </message>
    <message>
        <source>striking…</source>
        <translation>számolás…</translation>
    </message>
    <message>
        <source>Striking the shot up to %1 times.</source>
        <translation>Az ütés ismétlése legfeljebb %1 alkalommal.</translation>
    </message>
    <message>
        <source>goes in %1 % (%2–%3 %)</source>
        <translation>%1%-ban megy be (%2–%3%)</translation>
    </message>
    <message>
        <source>meets the goal %1 % (%2–%3 %)</source>
        <translation>%1%-ban teljesíti a célt (%2–%3%)</translation>
    </message>
    <message>
        <source>%1 of %2 strikes met the goal</source>
        <translation>%2 ütésből %1 teljesítette a célt</translation>
    </message>
    <message>
        <source>; %1 miscues (tip beyond 0.5 R)</source>
        <translation>; %1 lecsúszás (a dákóvég 0,5 R-en túl)</translation>
    </message>
    <message>
        <source>; stopped once the interval was within ±1%</source>
        <translation>; megállt, amikor az intervallum ±1%-on belülre került</translation>
    </message>
    <message>
        <source>Choose two keys of this setup.</source>
        <translation>Válasszon két kulcsot ebből a felállásból.</translation>
    </message>
    <message>
        <source>Choose two different keys.</source>
        <translation>Válasszon két különböző kulcsot.</translation>
    </message>
    <message>
        <source>Mapping the odds of %1 shots, %2 strikes each.</source>
        <translation>%1 ütés esélyeinek térképezése, mindegyik %2 ütéssel.</translation>
    </message>
    <message>
        <source>Best cell (ringed): %1. Click a cell to load its shot.</source>
        <translation>Legjobb cella (bekarikázva): %1. Egy cellára kattintva betölti az ütését.</translation>
    </message>
    <message>
        <source>No cell of the map is a legal shot.</source>
        <translation>A térkép egyetlen cellája sem szabályos ütés.</translation>
    </message>
    <message>
        <source>The setup changed since the map was made; map again.</source>
        <translation>A felállás megváltozott a térkép készítése óta; térképezzen újra.</translation>
    </message>
    <message>
        <source>Load shot from the odds map (%1 = %2, %3 = %4)</source>
        <translation>Ütés betöltése az esélytérképről (%1 = %2, %3 = %4)</translation>
    </message>
    <message>
        <source>That cell&apos;s shot is not a legal setup.</source>
        <translation>Ennek a cellának az ütése nem szabályos felállás.</translation>
    </message>
    <message>
        <source>the shot changed: press Odds</source>
        <translation>az ütés megváltozott: nyomja meg az Esély gombot</translation>
    </message>
    <message>
        <source>The setup changed: the map of odds was dropped.</source>
        <translation>A felállás megváltozott: az esélytérkép elveszett.</translation>
    </message>
</context>
<context>
    <name>cuelab::OutcomeMap</name>
    <message>
        <source>No map yet: choose the axes and press Map.</source>
        <translation>Még nincs térkép: válassza ki a tengelyeket, és nyomja meg a Térkép gombot.</translation>
    </message>
</context>
<context>
    <name>cuelab::OutcomePanel</name>
    <message>
        <source>What</source>
        <translation>Tétel</translation>
    </message>
    <message>
        <source>Outcome</source>
        <translation>Eredmény</translation>
    </message>
    <message>
        <source>Double-click the first contact or a pocketing to go to that event</source>
        <translation>Dupla kattintás az első érintkezésre vagy egy lyukba esésre: ugrás arra az eseményre</translation>
    </message>
    <message>
        <source>Ball</source>
        <translation>Golyó</translation>
    </message>
    <message>
        <source>Cushions</source>
        <translation>Mantinelek</translation>
    </message>
    <message>
        <source>Ends</source>
        <translation>Végső hely</translation>
    </message>
    <message>
        <source>x, y (m)</source>
        <translation>x, y (m)</translation>
    </message>
    <message>
        <source>Per ball: ball-cushion contacts (jaws included) and where it ends; double-click selects it</source>
        <translation>Golyónként: golyó–mantinel érintkezések (a lyukpofákkal együtt) és hová kerül végül; dupla kattintással kijelölhető</translation>
    </message>
    <message>
        <source>No simulation yet</source>
        <translation>Még nincs szimuláció</translation>
    </message>
    <message>
        <source>Struck ball</source>
        <translation>Megütött golyó</translation>
    </message>
    <message>
        <source>none (no shot)</source>
        <translation>nincs (nincs ütés)</translation>
    </message>
    <message>
        <source>First contact</source>
        <translation>Első érintkezés</translation>
    </message>
    <message>
        <source>%1 at %2 s</source>
        <translation>%1, %2 s-nál</translation>
    </message>
    <message>
        <source>The first ball the struck ball touches, and when (s)</source>
        <translation>Az első golyó, amelyet a megütött golyó eltalál, és mikor (s)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>nincs</translation>
    </message>
    <message>
        <source>Cushions before it</source>
        <translation>Mantinelek előtte</translation>
    </message>
    <message>
        <source>Ball-cushion contacts of the struck ball before its first contact (jaws included)</source>
        <translation>A megütött golyó mantinelérintései az első érintkezése előtt (a lyukpofákkal együtt)</translation>
    </message>
    <message>
        <source>Pocketed</source>
        <translation>Lyukba esett</translation>
    </message>
    <message>
        <source>Struck ball pocketed</source>
        <translation>A megütött golyó lyukba esett</translation>
    </message>
    <message>
        <source>yes (a scratch)</source>
        <translation>igen (hiba: a megütött golyó beesett)</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nem</translation>
    </message>
    <message>
        <source>Final position in metres (table frame)</source>
        <translation>Végső hely méterben (az asztal koordináta-rendszerében)</translation>
    </message>
    <message>
        <source>%1 in the %2 at %3 s</source>
        <translation>%1: %2ban, %3 s-nál</translation>
    </message>
    <message>
        <source>Against the recording</source>
        <translation>A felvételhez mérve</translation>
    </message>
    <message>
        <source>RMSE (cm) of the recorded samples against the simulated balls (the Recording dock has the details)</source>
        <translation>A rögzített minták négyzetes középeltérése (cm) a szimulált golyókhoz képest (részletek a Felvétel panelen)</translation>
    </message>
    <message>
        <source>in the %1</source>
        <translation>%1ban</translation>
    </message>
</context>
<context>
    <name>cuelab::PhysicsPanel</name>
    <message>
        <source>Pockets</source>
        <translation>Lyukak</translation>
    </message>
    <message>
        <source>Without pockets the rails are closed all round (a carom table never has pockets)</source>
        <translation>Lyukak nélkül a mantinel körben zárt (a karambolasztalon sosincs lyuk)</translation>
    </message>
    <message>
        <source>m/s²</source>
        <translation>m/s²</translation>
    </message>
    <message>
        <source>Gravitational acceleration g in m/s² (9.81 on Earth)</source>
        <translation>A nehézségi gyorsulás, g, m/s²-ben (a Földön 9,81)</translation>
    </message>
    <message>
        <source>Sliding friction between ball and cloth (dimensionless; 0.2, range 0.15-0.4, Alciatore)</source>
        <translation>Csúszási súrlódás a golyó és a posztó között (dimenzió nélküli; 0,2, tartomány 0,15–0,4, Alciatore)</translation>
    </message>
    <message>
        <source>Rolling resistance of the cloth (dimensionless; 0.01, range 0.005-0.015)</source>
        <translation>A posztó gördülési ellenállása (dimenzió nélküli; 0,01, tartomány 0,005–0,015)</translation>
    </message>
    <message>
        <source>Spin friction about the vertical axis (dimensionless; 0.0127 slows side spin by about 10.9 rad/s²)</source>
        <translation>Pörgési súrlódás a függőleges tengely körül (dimenzió nélküli; a 0,0127 kb. 10,9 rad/s²-tel lassítja az oldalpörgetést)</translation>
    </message>
    <message>
        <source>Frictionless</source>
        <translation>Súrlódásmentes</translation>
    </message>
    <message>
        <source>Frictional (throw)</source>
        <translation>Súrlódásos (elvitellel)</translation>
    </message>
    <message>
        <source>Ball-ball collision model: frictionless (spins unchanged) or with a Coulomb-limited tangential impulse that throws the object ball</source>
        <translation>A golyó–golyó ütközés modellje: súrlódásmentes (a pörgetések nem változnak) vagy Coulomb-korlátos érintőleges erőlökéssel, amely eltéríti (elviszi) a célgolyót</translation>
    </message>
    <message>
        <source>Ball-ball coefficient of restitution (dimensionless; 0.95, range 0.92-0.98)</source>
        <translation>A golyó–golyó ütközési tényező (restitúció; dimenzió nélküli; 0,95, tartomány 0,92–0,98)</translation>
    </message>
    <message>
        <source>Fixed</source>
        <translation>Állandó</translation>
    </message>
    <message>
        <source>Speed-dependent (Alciatore)</source>
        <translation>Sebességfüggő (Alciatore)</translation>
    </message>
    <message>
        <source>Ball-ball friction: a fixed coefficient, or Alciatore&apos;s fit 0.00995 + 0.108 exp(-1.088 v) of the relative speed v in m/s</source>
        <translation>Golyó–golyó súrlódás: állandó együttható, vagy Alciatore illesztése, 0,00995 + 0,108 exp(−1,088 v), ahol v a relatív sebesség m/s-ban</translation>
    </message>
    <message>
        <source>Fixed ball-ball friction coefficient (dimensionless; 0.05)</source>
        <translation>Állandó golyó–golyó súrlódási együttható (dimenzió nélküli; 0,05)</translation>
    </message>
    <message>
        <source>Ball-cushion coefficient of restitution (dimensionless; 0.85, range 0.6-0.9)</source>
        <translation>A golyó–mantinel ütközési tényező (restitúció; dimenzió nélküli; 0,85, tartomány 0,6–0,9)</translation>
    </message>
    <message>
        <source>Ball-cushion friction coefficient (dimensionless; 0.2)</source>
        <translation>A golyó–mantinel súrlódási együttható (dimenzió nélküli; 0,2)</translation>
    </message>
    <message>
        <source>ms</source>
        <translation>ms</translation>
    </message>
    <message>
        <source>Frame timestep in milliseconds: one step of frame-by-frame playback (16.667 ms = 60 frames per second)</source>
        <translation>Képkockalépés milliszekundumban: a kockánkénti lejátszás egy lépése (16,667 ms = 60 kép másodpercenként)</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>The simulation stops at this time in seconds at the latest</source>
        <translation>A szimuláció legkésőbb ennél az időpontnál (másodpercben) leáll</translation>
    </message>
    <message>
        <source>Reset to Defaults</source>
        <translation>Alapértékek visszaállítása</translation>
    </message>
    <message>
        <source>Set friction, restitution, models and gravity back to the defaults of the physics reference</source>
        <translation>A súrlódás, a restitúció, a modellek és a nehézségi gyorsulás visszaállítása a fizikai leírás alapértékeire</translation>
    </message>
    <message>
        <source>Table</source>
        <translation>Asztal</translation>
    </message>
    <message>
        <source>Kind</source>
        <translation>Fajta</translation>
    </message>
    <message>
        <source>Cloth</source>
        <translation>Posztó</translation>
    </message>
    <message>
        <source>μ slide</source>
        <translation>μ csúszás</translation>
    </message>
    <message>
        <source>μ roll</source>
        <translation>μ gördülés</translation>
    </message>
    <message>
        <source>μ spin</source>
        <translation>μ pörgés</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Nehézségi gyorsulás</translation>
    </message>
    <message>
        <source>Ball-ball</source>
        <translation>Golyó–golyó</translation>
    </message>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Restitution</source>
        <translation>Restitúció</translation>
    </message>
    <message>
        <source>Friction</source>
        <translation>Súrlódás</translation>
    </message>
    <message>
        <source>μ ball</source>
        <translation>μ golyó</translation>
    </message>
    <message>
        <source>Ball-cushion</source>
        <translation>Golyó–mantinel</translation>
    </message>
    <message>
        <source>μ cushion</source>
        <translation>μ mantinel</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Idő</translation>
    </message>
    <message>
        <source>Frame step</source>
        <translation>Képkockalépés</translation>
    </message>
    <message>
        <source>Stop at</source>
        <translation>Leállás</translation>
    </message>
    <message>
        <source>Change gravity</source>
        <translation>A nehézségi gyorsulás módosítása</translation>
    </message>
    <message>
        <source>Change μ slide</source>
        <translation>A csúszási μ módosítása</translation>
    </message>
    <message>
        <source>Change μ roll</source>
        <translation>A gördülési μ módosítása</translation>
    </message>
    <message>
        <source>Change μ spin</source>
        <translation>A pörgési μ módosítása</translation>
    </message>
    <message>
        <source>Change ball-ball restitution</source>
        <translation>A golyó–golyó restitúció módosítása</translation>
    </message>
    <message>
        <source>Change ball-ball friction</source>
        <translation>A golyó–golyó súrlódás módosítása</translation>
    </message>
    <message>
        <source>Change cushion restitution</source>
        <translation>A mantinel restitúciójának módosítása</translation>
    </message>
    <message>
        <source>Change cushion friction</source>
        <translation>A mantinel súrlódásának módosítása</translation>
    </message>
    <message>
        <source>Change the ball-ball model</source>
        <translation>A golyó–golyó modell módosítása</translation>
    </message>
    <message>
        <source>Change the ball-ball friction law</source>
        <translation>A golyó–golyó súrlódási törvény módosítása</translation>
    </message>
    <message>
        <source>Change the cushion model</source>
        <translation>A mantinelmodell módosítása</translation>
    </message>
    <message>
        <source>Change the frame step</source>
        <translation>A képkockalépés módosítása</translation>
    </message>
    <message>
        <source>Change the time limit</source>
        <translation>Az időkorlát módosítása</translation>
    </message>
    <message>
        <source>Change the table</source>
        <translation>Az asztal módosítása</translation>
    </message>
    <message>
        <source>Open the pockets</source>
        <translation>A lyukak megnyitása</translation>
    </message>
    <message>
        <source>Close the pockets</source>
        <translation>A lyukak lezárása</translation>
    </message>
    <message>
        <source>Ball-cushion model: mirror, Han 2005, Mathavan 2010 or Stronge&apos;s compliant impact (docs/cushion-models.md)</source>
        <translation>A golyó–mantinel modell: tükrözés, Han 2005, Mathavan 2010 vagy Stronge rugalmas ütközése (docs/cushion-models.md)</translation>
    </message>
    <message>
        <source>The table: playing surface between the cushion noses in metres, pockets and cushions of the preset. The balls keep their size and place; balls that would lie off the new cloth can be moved to the nearest free spots.</source>
        <translation>Az asztal: a játékfelület a mantinelek élei között, méterben, az előbeállítás lyukaival és mantineljeivel. A golyók megtartják méretüket és helyüket; az új posztón kívülre kerülő golyók áthelyezhetők a legközelebbi szabad helyekre.</translation>
    </message>
    <message>
        <source>Balls Off the New Table</source>
        <translation>Golyók az új asztalon kívül</translation>
    </message>
    <message numerus="yes">
        <source>On the %1 table (%2 × %3 m), %n ball(s) would lie off the cloth, in a pocket or on another ball: %4.</source>
        <translation>
            <numerusform>A(z) %1 asztalon (%2 × %3 m) %n golyó a posztón kívül, lyukban vagy egy másik golyón lenne: %4.</numerusform>
        </translation>
    </message>
    <message>
        <source>Move them to the nearest free spots? The table change and the moves are one undo step.</source>
        <translation>Áthelyezi őket a legközelebbi szabad helyekre? Az asztal módosítása és az áthelyezések egy visszavonási lépést alkotnak.</translation>
    </message>
    <message>
        <source>&amp;Move Balls</source>
        <translation>A golyók át&amp;helyezése</translation>
    </message>
</context>
<context>
    <name>cuelab::PlotsChartView</name>
    <message>
        <source>time (s)</source>
        <translation>idő (s)</translation>
    </message>
    <message>
        <source>events</source>
        <translation>események</translation>
    </message>
    <message>
        <source>selected event</source>
        <translation>kijelölt esemény</translation>
    </message>
    <message>
        <source>cursor</source>
        <translation>kurzor</translation>
    </message>
    <message>
        <source>Drag: move the time cursor. Wheel: zoom the time axis (Ctrl: the value axis). Shift-drag or middle-drag: pan. Double-click: show everything. Click a marker to select its event.</source>
        <translation>Húzás: az időkurzor mozgatása. Görgő: az időtengely nagyítása (Ctrl: az értéktengelyé). Shift+húzás vagy középső gombos húzás: eltolás. Dupla kattintás: minden látszik. Egy jelölőre kattintva kijelölhető az eseménye.</translation>
    </message>
</context>
<context>
    <name>cuelab::PlotsPanel</name>
    <message>
        <source>Speed (m/s)</source>
        <translation>Sebesség (m/s)</translation>
    </message>
    <message>
        <source>Slip speed (m/s)</source>
        <translation>Csúszási sebesség (m/s)</translation>
    </message>
    <message>
        <source>Spin wx, wy, wz (rad/s)</source>
        <translation>Pörgetés wx, wy, wz (rad/s)</translation>
    </message>
    <message>
        <source>Kinetic energy (J)</source>
        <translation>Mozgási energia (J)</translation>
    </message>
    <message>
        <source>What to plot against time (s). Slip speed: the speed of the ball&apos;s contact point on the cloth (m/s), zero while it rolls. Energy: translational, rotational and total (J).</source>
        <translation>Mit ábrázoljon az idő (s) függvényében. Csúszási sebesség: a golyó posztóval érintkező pontjának sebessége (m/s), gördülés közben nulla. Energia: haladó, forgó és teljes (J).</translation>
    </message>
    <message>
        <source>Selected ball</source>
        <translation>Kijelölt golyó</translation>
    </message>
    <message>
        <source>All balls</source>
        <translation>Minden golyó</translation>
    </message>
    <message>
        <source>The selected ball (the struck ball when none is selected) or every ball</source>
        <translation>A kijelölt golyó (ha nincs kijelölve, a megütött golyó) vagy minden golyó</translation>
    </message>
    <message>
        <source>Show all</source>
        <translation>Minden mutatása</translation>
    </message>
    <message>
        <source>Zoom out to the whole shot (double-click the chart)</source>
        <translation>Kicsinyítés a teljes ütésre (dupla kattintás a grafikonon)</translation>
    </message>
    <message>
        <source>No balls</source>
        <translation>Nincs golyó</translation>
    </message>
    <message>
        <source>No simulation yet</source>
        <translation>Még nincs szimuláció</translation>
    </message>
    <message>
        <source> speed</source>
        <translation> sebesség</translation>
    </message>
    <message>
        <source> slip</source>
        <translation> csúszás</translation>
    </message>
    <message>
        <source> wx</source>
        <translation> wx</translation>
    </message>
    <message>
        <source> wy</source>
        <translation> wy</translation>
    </message>
    <message>
        <source> wz</source>
        <translation> wz</translation>
    </message>
    <message>
        <source> wz (side)</source>
        <translation> wz (oldalpörgetés)</translation>
    </message>
    <message>
        <source> translation</source>
        <translation> haladó</translation>
    </message>
    <message>
        <source> rotation</source>
        <translation> forgó</translation>
    </message>
    <message>
        <source> total</source>
        <translation> teljes</translation>
    </message>
    <message>
        <source>table total</source>
        <translation>az asztal összesen</translation>
    </message>
    <message>
        <source>Event %1: %2 (%3) at %4 s</source>
        <translation>%1. esemény: %2 (%3), %4 s-nál</translation>
    </message>
    <message>
        <source>Ball %1</source>
        <translation>%1 golyó</translation>
    </message>
    <message numerus="yes">
        <source>%n event(s)</source>
        <translation>
            <numerusform>%n esemény</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cuelab::PredictPanel</name>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>stays</source>
        <translation>marad</translation>
    </message>
    <message>
        <source>spot on</source>
        <translation>telitalálat</translation>
    </message>
    <message>
        <source>close</source>
        <translation>közeli</translation>
    </message>
    <message>
        <source>off</source>
        <translation>mellé</translation>
    </message>
    <message>
        <source>right</source>
        <translation>helyes</translation>
    </message>
    <message>
        <source>wrong</source>
        <translation>téves</translation>
    </message>
    <message>
        <source>no answer</source>
        <translation>nincs válasz</translation>
    </message>
    <message>
        <source>Predict, then reveal: the shot stops before each question&apos;s event; drag from each ball where it will go, then reveal where it went.</source>
        <translation>Előbb jósoljon, aztán nézze meg: a lövés minden kérdés eseménye előtt megáll; húzzon minden golyótól arra, amerre menni fog, majd fedje fel, hová ment.</translation>
    </message>
    <message>
        <source>Stops before</source>
        <translation>Megáll ez előtt</translation>
    </message>
    <message>
        <source>Balls</source>
        <translation>Golyók</translation>
    </message>
    <message>
        <source>Question</source>
        <translation>Kérdés</translation>
    </message>
    <message>
        <source>The event the shot stops before (set when the question is added)</source>
        <translation>Az esemény, amely előtt a lövés megáll (a kérdés hozzáadásakor dől el)</translation>
    </message>
    <message>
        <source>The ids of the balls to predict, separated by commas; empty: the event&apos;s own balls</source>
        <translation>A megjósolandó golyók azonosítói vesszővel elválasztva; üresen: az esemény saját golyói</translation>
    </message>
    <message>
        <source>What the student reads; empty: &quot;Where will each ball go?&quot;</source>
        <translation>Amit a diák olvas; üresen: „Merre mennek majd a golyók?”</translation>
    </message>
    <message>
        <source>Add Question</source>
        <translation>Kérdés hozzáadása</translation>
    </message>
    <message>
        <source>Ask before the event selected in Events (the first collision when none is); one undo step</source>
        <translation>Kérdés az Események panelen kijelölt esemény előtt (ha nincs kijelölés, az első ütközés előtt); egy visszavonási lépés</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>Eltávolítás</translation>
    </message>
    <message>
        <source>Remove the selected question; one undo step</source>
        <translation>A kijelölt kérdés eltávolítása; egy visszavonási lépés</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Indítás</translation>
    </message>
    <message>
        <source>Play the shot from the start and stop before each question (without questions: before the first collision)</source>
        <translation>A lövés lejátszása az elejétől, megállással minden kérdés előtt (kérdések nélkül: az első ütközés előtt)</translation>
    </message>
    <message>
        <source>Reveal</source>
        <translation>Felfedés</translation>
    </message>
    <message>
        <source>Show where each ball went beside your guess, with the angle between them in degrees, and play on</source>
        <translation>Megmutatja a tippje mellett, hová ment az egyes golyó, a kettő szögeltérésével fokban, és folytatja a lejátszást</translation>
    </message>
    <message>
        <source>#</source>
        <translation>#</translation>
    </message>
    <message>
        <source>Ball</source>
        <translation>Golyó</translation>
    </message>
    <message>
        <source>Your guess</source>
        <translation>Tipp</translation>
    </message>
    <message>
        <source>Went</source>
        <translation>Valójában</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Eltérés</translation>
    </message>
    <message>
        <source>Score</source>
        <translation>Pontszám</translation>
    </message>
    <message>
        <source>Your direction, in degrees (0° = along the table&apos;s length, counter-clockwise)</source>
        <translation>Az Ön által adott irány fokban (0° = az asztal hossza mentén, az óramutatóval ellentétesen nő)</translation>
    </message>
    <message>
        <source>Where the ball went, in degrees: its direction once it stops sliding, or before its next collision</source>
        <translation>Ahová a golyó ment, fokban: az iránya, amikor már nem csúszik, vagy a következő ütközése előtt</translation>
    </message>
    <message>
        <source>The angle between your guess and where it went, in degrees (0° to 180°)</source>
        <translation>A tipp és a valódi irány közti szög fokban (0°–180°)</translation>
    </message>
    <message>
        <source>100 % for a perfect guess, falling to 0 % at 90° off; a right &quot;stays&quot; scores 100 %</source>
        <translation>Pontos tipp 100 %, 90° eltérésnél 0 %-ra csökken; egy helyes „marad” 100 %</translation>
    </message>
    <message>
        <source>the first collision</source>
        <translation>az első ütközés</translation>
    </message>
    <message>
        <source>%1 %2 at %3 s</source>
        <translation>%1 %2, %3 s-nál</translation>
    </message>
    <message>
        <source>%1 (not in this shot)</source>
        <translation>%1 (nincs ebben a lövésben)</translation>
    </message>
    <message>
        <source>Add a lesson question</source>
        <translation>Leckekérdés hozzáadása</translation>
    </message>
    <message>
        <source>Remove lesson question %1</source>
        <translation>A(z) %1. leckekérdés eltávolítása</translation>
    </message>
    <message>
        <source>Edit lesson question %1</source>
        <translation>A(z) %1. leckekérdés szerkesztése</translation>
    </message>
    <message>
        <source>There is no ball &quot;%1&quot; in the shot.</source>
        <translation>A lövésben nincs „%1” golyó.</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Leállítás</translation>
    </message>
    <message>
        <source>Playing to the first question…</source>
        <translation>Lejátszás az első kérdésig…</translation>
    </message>
    <message>
        <source>Where will each ball go?</source>
        <translation>Merre mennek majd a golyók?</translation>
    </message>
    <message>
        <source>Question %1 of %2: %3
Drag from each ball where it will go (a click on a ball: it stays). %4 of %5 answered.</source>
        <translation>%1. kérdés a(z) %2 közül: %3
Húzzon minden golyótól arra, amerre menni fog (kattintás egy golyóra: helyben marad). %5 golyóból %4 megválaszolva.</translation>
    </message>
    <message>
        <source>Revealed. Playing on to question %1…</source>
        <translation>Felfedve. Lejátszás tovább a(z) %1. kérdésig…</translation>
    </message>
    <message>
        <source>Revealed. Playing on to the end…</source>
        <translation>Felfedve. Lejátszás tovább a végéig…</translation>
    </message>
    <message>
        <source>Done: %1 of %2 questions, mean score %3 %.</source>
        <translation>Kész: %2 kérdésből %1 megválaszolva, átlagos pontszám %3 %.</translation>
    </message>
    <message>
        <source>
Not asked: %1</source>
        <translation>
Kimaradt kérdés: %1</translation>
    </message>
    <message>
        <source>—</source>
        <translation>—</translation>
    </message>
    <message>
        <source>%1° (%2)</source>
        <translation>%1° (%2)</translation>
    </message>
    <message>
        <source>%1 %</source>
        <translation>%1 %</translation>
    </message>
</context>
<context>
    <name>cuelab::PredictSession</name>
    <message>
        <source>The shot is still being simulated; try again in a moment.</source>
        <translation>A lövés szimulációja még fut; próbálja újra egy pillanat múlva.</translation>
    </message>
    <message>
        <source>This shot has no collision to predict.</source>
        <translation>Ebben a lövésben nincs megjósolható ütközés.</translation>
    </message>
    <message>
        <source>%1: drag where it goes</source>
        <translation>%1: húzza arra, amerre megy</translation>
    </message>
    <message>
        <source>%1: your guess</source>
        <translation>%1: az Ön tippje</translation>
    </message>
    <message>
        <source>%1: you say it stays</source>
        <translation>%1: Ön szerint helyben marad</translation>
    </message>
    <message>
        <source>%1: went here, %2° off</source>
        <translation>%1: ide ment, %2°-os eltérés</translation>
    </message>
    <message>
        <source>%1: went here</source>
        <translation>%1: ide ment</translation>
    </message>
    <message>
        <source>%1: stayed</source>
        <translation>%1: helyben maradt</translation>
    </message>
    <message>
        <source>Pink: your guess · green: where the ball went</source>
        <translation>Rózsaszín: az Ön tippje · zöld: ahová a golyó ment</translation>
    </message>
    <message>
        <source>Drag from each ball where it will go; click a ball that stays</source>
        <translation>Húzzon minden golyótól arra, amerre menni fog; kattintson arra a golyóra, amely helyben marad</translation>
    </message>
</context>
<context>
    <name>cuelab::RecentFiles</name>
    <message>
        <source>&amp;Clear List</source>
        <translation>A lista &amp;törlése</translation>
    </message>
</context>
<context>
    <name>cuelab::RecordingPanel</name>
    <message>
        <source>∞</source>
        <translation>∞</translation>
    </message>
    <message>
        <source>%1 cm</source>
        <translation>%1 cm</translation>
    </message>
    <message>
        <source>Distance (cm) between each recorded sample and the simulated ball at the sample&apos;s time (s), one line per ball: where the model and the recording part</source>
        <translation>Az egyes rögzített minták távolsága (cm) a szimulált golyótól a minta idejében (s), golyónként egy vonal: ahol a modell és a felvétel elválik</translation>
    </message>
    <message>
        <source>The residual over time, once a recording is open</source>
        <translation>Az eltérés az idő függvényében, ha van megnyitott felvétel</translation>
    </message>
    <message>
        <source>Distance to the simulation (cm)</source>
        <translation>Távolság a szimulációtól (cm)</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Root mean square of the distances (cm) between the recorded samples and the simulated balls at the same times: over the struck ball, and over every recorded ball</source>
        <translation>A rögzített minták és az azonos idejű szimulált golyók távolságainak négyzetes közepe (cm): a megütött golyóra és minden rögzített golyóra</translation>
    </message>
    <message>
        <source>Ball</source>
        <translation>Golyó</translation>
    </message>
    <message>
        <source>Samples</source>
        <translation>Minták</translation>
    </message>
    <message>
        <source>RMSE</source>
        <translation>RMSE</translation>
    </message>
    <message>
        <source>Per recorded ball: its samples and their RMSE (cm) against the simulation</source>
        <translation>Rögzített golyónként: a minták száma és négyzetes középeltérésük (cm) a szimulációhoz képest</translation>
    </message>
    <message>
        <source>Fit Strike</source>
        <translation>Ütés illesztése</translation>
    </message>
    <message>
        <source>Find the heading (°), cue speed (m/s) and tip offsets (R) whose simulation follows the recording best (the same fit as cuelab-cli fit); the result is one undoable edit</source>
        <translation>Az irány (°), a dákósebesség (m/s) és a dákóvég-eltolások (R) megkeresése, amelyek szimulációja a legjobban követi a felvételt (ugyanaz az illesztés, mint a cuelab-cli fit); az eredmény egy visszavonható szerkesztés</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Mégse</translation>
    </message>
    <message>
        <source>Stop the fit; the shot stays as it was</source>
        <translation>Az illesztés leállítása; az ütés változatlan marad</translation>
    </message>
    <message>
        <source>Local searches of the fit done</source>
        <translation>Az illesztés elvégzett helyi keresései</translation>
    </message>
    <message>
        <source>struck ball %1, every ball %2</source>
        <translation>megütött golyó %1, minden golyó %2</translation>
    </message>
    <message>
        <source>No recording open. File → Open Recording… reads a tracked shot (cuelab-recording JSON or CSV) and shows it against the simulation.</source>
        <translation>Nincs megnyitott felvétel. A Fájl → Felvétel megnyitása… beolvas egy követett ütést (cuelab-recording JSON vagy CSV), és a szimulációval együtt mutatja.</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;: %2 recorded balls, %3 s</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;: %2 rögzített golyó, %3 s</translation>
    </message>
    <message>
        <source>The shot has no ball &quot;%1&quot;: open the recording again to start from its own setup.</source>
        <translation>Az ütésben nincs „%1” golyó: nyissa meg újra a felvételt, hogy a saját felállásából induljon.</translation>
    </message>
    <message>
        <source>RMSE: %1</source>
        <translation>RMSE: %1</translation>
    </message>
    <message>
        <source>Fit cancelled: the shot is as it was</source>
        <translation>Illesztés megszakítva: az ütés változatlan</translation>
    </message>
    <message>
        <source>Fit the strike to the recording</source>
        <translation>Az ütés illesztése a felvételhez</translation>
    </message>
    <message>
        <source>Strike fitted in %1 s: RMSE %2 (moved balls); Edit → Undo takes it back</source>
        <translation>Ütés illesztve %1 s alatt: RMSE %2 (mozgó golyók); Szerkesztés → Visszavonás visszaveszi</translation>
    </message>
    <message>
        <source>The fitted strike was refused</source>
        <translation>Az illesztett ütést a felállás nem fogadta el</translation>
    </message>
    <message>
        <source>Calibrate Cloth</source>
        <translation>Posztó kalibrálása</translation>
    </message>
    <message>
        <source>Fit the rolling resistance μr and the sliding friction μs (no unit) over every recording opened in this session, each with its own strike (the same calibration as cuelab-cli calibrate); the frictions and this recording&apos;s strike are one undoable edit</source>
        <translation>A gördülési ellenállás μr és a csúszási súrlódás μs (mértékegység nélkül) illesztése az ebben a munkamenetben megnyitott összes felvételre, mindegyiknek a saját ütésével (ugyanaz a kalibrálás, mint a cuelab-cli calibrate); a súrlódások és ennek a felvételnek az ütése egy visszavonható szerkesztés</translation>
    </message>
    <message>
        <source>%1 recordings open in this session (Calibrate Cloth uses them all)</source>
        <translation>%1 felvétel van nyitva ebben a munkamenetben (a posztó kalibrálása mindet használja)</translation>
    </message>
    <message>
        <source>Calibrate the cloth to the recordings</source>
        <translation>A posztó kalibrálása a felvételekhez</translation>
    </message>
    <message>
        <source>Cloth calibrated: μr = %1, μs = %2; RMSE %3 (moved balls); Edit → Undo takes it back</source>
        <translation>Posztó kalibrálva: μr = %1, μs = %2; RMSE %3 (mozgó golyók); Szerkesztés → Visszavonás visszaveszi</translation>
    </message>
</context>
<context>
    <name>cuelab::ShortcutsDialog</name>
    <message>
        <source>Table view</source>
        <translation>Asztalnézet</translation>
    </message>
    <message>
        <source>Panels</source>
        <translation>Panelek</translation>
    </message>
    <message>
        <source>Select a ball</source>
        <translation>Golyó kijelölése</translation>
    </message>
    <message>
        <source>Click the ball</source>
        <translation>Kattintás a golyóra</translation>
    </message>
    <message>
        <source>Move a ball (at t = 0)</source>
        <translation>Golyó áthelyezése (t = 0-kor)</translation>
    </message>
    <message>
        <source>Drag the ball; it lands on the nearest free spot</source>
        <translation>A golyó húzása; a legközelebbi szabad helyre kerül</translation>
    </message>
    <message>
        <source>Orbit the camera</source>
        <translation>A kamera körbeforgatása</translation>
    </message>
    <message>
        <source>Drag on the cloth or the background</source>
        <translation>Húzás a posztón vagy a háttéren</translation>
    </message>
    <message>
        <source>Pan the camera</source>
        <translation>A kamera eltolása</translation>
    </message>
    <message>
        <source>Right or middle drag, or Shift + drag</source>
        <translation>Jobb vagy középső gombos húzás, vagy Shift + húzás</translation>
    </message>
    <message>
        <source>Zoom towards the cursor</source>
        <translation>Nagyítás a kurzor felé</translation>
    </message>
    <message>
        <source>Mouse wheel</source>
        <translation>Egérgörgő</translation>
    </message>
    <message>
        <source>Centre the camera on a point</source>
        <translation>A kamera ráirányítása egy pontra</translation>
    </message>
    <message>
        <source>Double-click</source>
        <translation>Dupla kattintás</translation>
    </message>
    <message>
        <source>Edit a value</source>
        <translation>Érték szerkesztése</translation>
    </message>
    <message>
        <source>Double-click a cell, type, Enter</source>
        <translation>Dupla kattintás egy cellára, gépelés, Enter</translation>
    </message>
    <message>
        <source>Place the cue tip</source>
        <translation>A dákóvég elhelyezése</translation>
    </message>
    <message>
        <source>Click or drag on the ball face in Shot</source>
        <translation>Kattintás vagy húzás a golyó lapján az Ütés panelen</translation>
    </message>
    <message>
        <source>Jump to an event</source>
        <translation>Ugrás egy eseményre</translation>
    </message>
    <message>
        <source>Click its row in Events</source>
        <translation>Kattintás a sorára az Események panelen</translation>
    </message>
    <message>
        <source>Scrub time</source>
        <translation>Léptetés az időben</translation>
    </message>
    <message>
        <source>Drag the time slider; ticks mark events</source>
        <translation>Az idő csúszkájának húzása; a jelek az eseményeket mutatják</translation>
    </message>
    <message>
        <source>Open a setup</source>
        <translation>Felállás megnyitása</translation>
    </message>
    <message>
        <source>Drop a .json file on the window</source>
        <translation>Egy .json fájl ráejtése az ablakra</translation>
    </message>
    <message>
        <source>Keyboard and Mouse</source>
        <translation>Billentyűzet és egér</translation>
    </message>
    <message>
        <source>Action</source>
        <translation>Művelet</translation>
    </message>
    <message>
        <source>Keys or gesture</source>
        <translation>Billentyűk vagy mozdulat</translation>
    </message>
    <message>
        <source>Keyboard</source>
        <translation>Billentyűzet</translation>
    </message>
    <message>
        <source>Mouse</source>
        <translation>Egér</translation>
    </message>
</context>
<context>
    <name>cuelab::ShotDiagram</name>
    <message>
        <source>Outcome: %1</source>
        <translation>Eredmény: %1</translation>
    </message>
    <message>
        <source>Balls where they rest (t = %1). </source>
        <translation>A golyók nyugalmi helyükön (t = %1). </translation>
    </message>
    <message>
        <source>Balls at t = %1 of %2; paths dashed after it. </source>
        <translation>A golyók t = %1-nál (összesen %2); utána a pályák szaggatottak. </translation>
    </message>
    <message>
        <source>Dashed rings: start positions. ◆ blue: ball-ball contact, ◆ red: cushion, ▲ pocketed.</source>
        <translation>Szaggatott körök: kezdőhelyek. ◆ kék: golyó–golyó érintkezés, ◆ piros: mantinel, ▲ lyukba esett.</translation>
    </message>
    <message>
        <source>The shot</source>
        <translation>Az ütés</translation>
    </message>
    <message>
        <source>The physics</source>
        <translation>A fizika</translation>
    </message>
</context>
<context>
    <name>cuelab::ShotPanel</name>
    <message>
        <source>Strike a ball at t = 0</source>
        <translation>Egy golyó megütése t = 0-kor</translation>
    </message>
    <message>
        <source>Without a strike the balls move only with the velocities and spins they are set up with.</source>
        <translation>Ütés nélkül a golyók csak a beállított sebességükkel és pörgetésükkel mozognak.</translation>
    </message>
    <message>
        <source>The ball the cue strikes</source>
        <translation>A golyó, amelyet a dákó megüt</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>Cue speed V0 in m/s just before the tip meets the ball</source>
        <translation>A dákó sebessége, V0, m/s-ban, közvetlenül mielőtt a dákóvég eléri a golyót</translation>
    </message>
    <message>
        <source>Heading of the cue in degrees: 0 = along +x (towards the foot rail), counter-clockwise positive</source>
        <translation>A dákó iránya fokban: 0 = a +x mentén (az alsó mantinel felé), az óramutató járásával ellentétesen pozitív</translation>
    </message>
    <message>
        <source>Elevation of the cue above the cloth in degrees (masse and jump shots)</source>
        <translation>A dákó emelése a posztó fölé, fokban (massé és ugratás)</translation>
    </message>
    <message>
        <source>Side offset of the tip as a fraction of the ball radius R: + = right of centre (right english)</source>
        <translation>A dákóvég oldalirányú eltolása a golyó R sugarának arányában: + = a középtől jobbra (jobb oldalpörgetés)</translation>
    </message>
    <message>
        <source>Height offset of the tip as a fraction of the ball radius R: + = above centre (follow), 0.4 R = natural roll</source>
        <translation>A dákóvég magassági eltolása a golyó R sugarának arányában: + = a közép fölött (felső, utánfutó ütés), 0,4 R = természetes gördülés</translation>
    </message>
    <message>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <source>Mass of the cue in kg (a typical cue: 0.567 kg, 20 oz)</source>
        <translation>A dákó tömege kg-ban (egy szokásos dákó: 0,567 kg, 20 uncia)</translation>
    </message>
    <message>
        <source>Ball</source>
        <translation>Golyó</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Sebesség</translation>
    </message>
    <message>
        <source>Heading</source>
        <translation>Irány</translation>
    </message>
    <message>
        <source>Elevation</source>
        <translation>Emelés</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Oldal</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Magasság</translation>
    </message>
    <message>
        <source>Tip</source>
        <translation>Dákóvég</translation>
    </message>
    <message>
        <source>Cue mass</source>
        <translation>Dákótömeg</translation>
    </message>
    <message>
        <source>Add the cue strike</source>
        <translation>A dákóütés hozzáadása</translation>
    </message>
    <message>
        <source>Remove the cue strike</source>
        <translation>A dákóütés eltávolítása</translation>
    </message>
    <message>
        <source>Strike ball %1</source>
        <translation>A(z) %1 golyó megütése</translation>
    </message>
    <message>
        <source>Change the cue speed</source>
        <translation>A dákó sebességének módosítása</translation>
    </message>
    <message>
        <source>Change the heading</source>
        <translation>Az irány módosítása</translation>
    </message>
    <message>
        <source>Change the cue elevation</source>
        <translation>A dákó emelésének módosítása</translation>
    </message>
    <message>
        <source>Move the cue tip</source>
        <translation>A dákóvég áthelyezése</translation>
    </message>
    <message>
        <source>Change the cue mass</source>
        <translation>A dákó tömegének módosítása</translation>
    </message>
    <message>
        <source>End mass</source>
        <translation>Végtömeg</translation>
    </message>
</context>
<context>
    <name>cuelab::SquirtControl</name>
    <message>
        <source>Squirt</source>
        <translation>Elcsúszás</translation>
    </message>
    <message>
        <source>Squirt: side english sends the cue ball off the cue line, away from the side of the english, by an angle that grows as the tip&apos;s end mass grows (Alciatore TP A-31). Off: the ball leaves along the cue line.</source>
        <translation>Elcsúszás (squirt): az oldalpörgetés a dákó vonalától elviszi a fehér golyót, a pörgetéssel ellentétes oldalra, annál nagyobb szögben, minél nagyobb a dákóvég tömege (Alciatore TP A-31). Kikapcsolva: a golyó a dákó vonalában indul.</translation>
    </message>
    <message>
        <source>g</source>
        <translation>g</translation>
    </message>
    <message>
        <source>End mass of the cue tip in grams, the part of the shaft that moves with the tip during the hit (about 5.7 g for a pool cue, a thirtieth of the ball; low-squirt shafts are lighter)</source>
        <translation>A dákóvég végtömege grammban: a szár azon része, amely az ütés alatt a dákóvéggel együtt mozog (pooldákónál kb. 5,7 g, a golyó harmincad része; a kis elcsúszású szárak könnyebbek)</translation>
    </message>
    <message>
        <source>Turn squirt on</source>
        <translation>Az elcsúszás bekapcsolása</translation>
    </message>
    <message>
        <source>Turn squirt off</source>
        <translation>Az elcsúszás kikapcsolása</translation>
    </message>
    <message>
        <source>Change the end mass</source>
        <translation>A végtömeg módosítása</translation>
    </message>
</context>
<context>
    <name>cuelab::TableInteraction</name>
    <message>
        <source>the spot under it is off the cloth, on a cushion or in a pocket</source>
        <translation>az alatta lévő hely a posztón kívül, mantinelen vagy lyukban van</translation>
    </message>
    <message>
        <source>the spot under it overlaps ball &quot;%1&quot;</source>
        <translation>az alatta lévő hely átfed a(z) „%1” golyóval</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>Ball &quot;%1&quot; placed %2 from the cursor, on the nearest free spot: %3.</source>
        <translation>A(z) „%1” golyó a kurzortól %2 távolságra, a legközelebbi szabad helyre került: %3.</translation>
    </message>
</context>
<context>
    <name>cuelab::TimelineSlider</name>
    <message>
        <source>Time since the strike; a tick marks every event</source>
        <translation>Az ütés óta eltelt idő; minden eseményt egy jel mutat</translation>
    </message>
</context>
<context>
    <name>cuelab::TipOffsetWidget</name>
    <message>
        <source>Cue tip offset on the ball&apos;s face, as the player sees it. Click or drag to place the tip; the dashed circle is the miscue limit (half the radius).</source>
        <translation>A dákóvég eltolása a golyó lapján, ahogy a játékos látja. Kattintással vagy húzással helyezhető el; a szaggatott kör a lecsúszás határa (a sugár fele).</translation>
    </message>
</context>
<context>
    <name>cuelab::ToiChart</name>
    <message>
        <source>No time-of-impact polynomial: this event&apos;s time is closed-form</source>
        <translation>Nincs ütközésiidő-polinom: ennek az eseménynek az időpontja zárt alakban adódik</translation>
    </message>
    <message>
        <source>Time-of-impact polynomial</source>
        <translation>Ütközésiidő-polinom</translation>
    </message>
    <message>
        <source>f(τ) from t₀ = %1 s</source>
        <translation>f(τ), t₀ = %1 s-tól</translation>
    </message>
    <message>
        <source>f = 0</source>
        <translation>f = 0</translation>
    </message>
    <message>
        <source>τ (s)</source>
        <translation>τ (s)</translation>
    </message>
    <message>
        <source>f (m)</source>
        <translation>f (m)</translation>
    </message>
    <message>
        <source>f (m²)</source>
        <translation>f (m²)</translation>
    </message>
    <message>
        <source>f(τ)</source>
        <translation>f(τ)</translation>
    </message>
    <message>
        <source>other roots</source>
        <translation>további gyökök</translation>
    </message>
    <message>
        <source>τ* = %1 s</source>
        <translation>τ* = %1 s</translation>
    </message>
</context>
<context>
    <name>cuelab::ToleranceBar</name>
    <message>
        <source>not scanned</source>
        <translation>nincs letapogatva</translation>
    </message>
    <message>
        <source> (the current value misses)</source>
        <translation> (az aktuális érték nem teljesíti)</translation>
    </message>
    <message>
        <source>%1 shots simulated; the window&apos;s edges are refined by bisection. Grey: misses the goal, dark: illegal value, green: meets it; the black line is the current value.</source>
        <translation>%1 ütés szimulálva; az ablak széleit felezéssel finomítja. Szürke: nem teljesíti a célt, sötét: szabálytalan érték, zöld: teljesíti; a fekete vonal az aktuális érték.</translation>
    </message>
    <message>
        <source>%1: from %2 to %3, ±%4</source>
        <translation>%1: %2 és %3 között, ±%4</translation>
    </message>
    <message>
        <source> (reaches the end of the scan)</source>
        <translation> (eléri a letapogatás végét)</translation>
    </message>
    <message>
        <source>%1: no value in the scanned range meets the goal</source>
        <translation>%1: a letapogatott tartomány egyetlen értéke sem teljesíti a célt</translation>
    </message>
</context>
<context>
    <name>cuelab::TransportBar</name>
    <message>
        <source>&amp;Start</source>
        <translation>&amp;Eleje</translation>
    </message>
    <message>
        <source>Go to the start, t = 0</source>
        <translation>Ugrás az elejére, t = 0</translation>
    </message>
    <message>
        <source>&amp;Previous Event</source>
        <translation>Elő&amp;ző esemény</translation>
    </message>
    <message>
        <source>Go to the previous event</source>
        <translation>Ugrás az előző eseményre</translation>
    </message>
    <message>
        <source>Frame &amp;Back</source>
        <translation>Egy kockát &amp;vissza</translation>
    </message>
    <message>
        <source>One frame back (the frame step is set in Physics)</source>
        <translation>Egy képkocka vissza (a képkockalépés a Fizika panelen állítható)</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Lejátszás</translation>
    </message>
    <message>
        <source>Play or pause</source>
        <translation>Lejátszás vagy szünet</translation>
    </message>
    <message>
        <source>Frame &amp;Forward</source>
        <translation>Egy kockát &amp;előre</translation>
    </message>
    <message>
        <source>One frame forward</source>
        <translation>Egy képkocka előre</translation>
    </message>
    <message>
        <source>&amp;Next Event</source>
        <translation>&amp;Következő esemény</translation>
    </message>
    <message>
        <source>Go to the next event</source>
        <translation>Ugrás a következő eseményre</translation>
    </message>
    <message>
        <source>&amp;End</source>
        <translation>&amp;Vége</translation>
    </message>
    <message>
        <source>Go to the end, when every ball rests</source>
        <translation>Ugrás a végére, amikor minden golyó nyugalomban van</translation>
    </message>
    <message>
        <source>Playback speed: 1× is real time</source>
        <translation>Lejátszási sebesség: az 1× a valós idő</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Szünet</translation>
    </message>
    <message>
        <source>Current time in seconds. Type a time (1.25, 1.25 s, 40 ms) or an event number (#12) and press Return to go there</source>
        <translation>Az aktuális időpont másodpercben. Írjon be egy időpontot (1.25, 1.25 s, 40 ms) vagy egy eseményszámot (#12), és Enterrel odaugrik</translation>
    </message>
    <message>
        <source>time or #event</source>
        <translation>idő vagy #esemény</translation>
    </message>
    <message>
        <source>End time of the shot, in seconds: when every ball rests</source>
        <translation>Az ütés befejező időpontja másodpercben: amikor minden golyó nyugalomban van</translation>
    </message>
    <message>
        <source>/ %1 s</source>
        <translation>/ %1 s</translation>
    </message>
    <message>
        <source>Events are numbered from 1.</source>
        <translation>Az események számozása 1-gyel kezdődik.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is not a time.</source>
        <translation>„%1” nem időpont.</translation>
    </message>
    <message>
        <source>&quot;%1&quot; is neither a time (1.25, 1.25 s, 40 ms) nor an event number (#12).</source>
        <translation>„%1” se nem időpont (1.25, 1.25 s, 40 ms), se nem eseményszám (#12).</translation>
    </message>
    <message numerus="yes">
        <source>There is no event #%1: the shot has %n event(s).</source>
        <translation>
            <numerusform>Nincs #%1 esemény: az ütésnek %n eseménye van.</numerusform>
        </translation>
    </message>
</context>
<context>
    <name>cuelab::UndoHistoryPanel</name>
    <message>
        <source>Every edit since the setup was opened; click one to go back (or forward) to it</source>
        <translation>Minden szerkesztés a felállás megnyitása óta; egyre kattintva visszatér (vagy előreugrik) hozzá</translation>
    </message>
    <message>
        <source>Opened %1</source>
        <translation>Megnyitva: %1</translation>
    </message>
</context>
<context>
    <name>cuelab::UserGuide</name>
    <message>
        <source>CueLab User Guide</source>
        <translation>A CueLab felhasználói útmutatója</translation>
    </message>
    <message>
        <source>&amp;Back</source>
        <translation>&amp;Vissza</translation>
    </message>
    <message>
        <source>&amp;Contents</source>
        <translation>&amp;Tartalom</translation>
    </message>
</context>
<context>
    <name>cuelab::VideoExport</name>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>%1× slower</source>
        <translation>%1× lassítva</translation>
    </message>
</context>
</TS>
