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
        <source>Aim &amp;Line and Ghost Ball</source>
        <translation>&amp;Célzóvonal és szellemgolyó</translation>
    </message>
    <message>
        <source>In the table view: the struck ball&apos;s first contact, with the ghost ball (where its centre is at contact), the aim line through it, the line of centres, the cut angle in degrees and the ball fraction</source>
        <translation>Az asztalnézetben: a megütött golyó első érintkezése a szellemgolyóval (ahol a középpontja az érintkezéskor van), a rajta átmenő célzóvonallal, a középpontokat összekötő egyenessel, a vágási szöggel fokban és a golyóhányaddal</translation>
    </message>
    <message>
        <source>&amp;Centre-of-Mass Frame</source>
        <translation>&amp;Tömegközépponti rendszer</translation>
    </message>
    <message>
        <source>Draw the selected collision&apos;s momenta (N·s), its paths near the event and the momenta diagram as seen from the pair&apos;s centre of mass, where the momenta are equal and opposite</source>
        <translation>A kijelölt ütközés lendületei (N·s), az esemény körüli pályák és a lendületábra a golyópár tömegközéppontjából nézve, ahol a lendületek egyenlő nagyságúak és ellentétesek</translation>
    </message>
    <message>
        <source>Predict</source>
        <translation>Jóslás</translation>
    </message>
    <message>
        <source>&amp;Find shots</source>
        <translation>&amp;Lökések keresése</translation>
    </message>
    <message>
        <source>The strikes that meet the goal most often for the chosen player</source>
        <translation>Azok a lökések, amelyek a választott játékosnál a leggyakrabban teljesítik a célt</translation>
    </message>
    <message>
        <source>Turn the cue</source>
        <translation>A dákó elfordítása</translation>
    </message>
    <message>
        <source>Pull back the cue</source>
        <translation>A dákó hátrahúzása</translation>
    </message>
    <message>
        <source>Aim through the ghost ball</source>
        <translation>Célzás a szellemgolyón át</translation>
    </message>
    <message>
        <source>Move the cue tip</source>
        <translation>A dákóvég áthelyezése</translation>
    </message>
</context>
<context>
    <name>cuelab</name>
    <message>
        <source>Verdict: %1</source>
        <translation>Ítélet: %1</translation>
    </message>
    <message>
        <source>a foul</source>
        <translation>szabálytalanság</translation>
    </message>
    <message>
        <source>a legal shot</source>
        <translation>szabályos lökés</translation>
    </message>
    <message>
        <source>the turn passes</source>
        <translation>a másik játékos következik</translation>
    </message>
    <message>
        <source>the striker plays on</source>
        <translation>a játékos folytatja</translation>
    </message>
    <message>
        <source>no point</source>
        <translation>nincs pont</translation>
    </message>
    <message>
        <source>a three-cushion point</source>
        <translation>háromfalas pont</translation>
    </message>
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
        <source>; off the table: %1</source>
        <translation>; az asztalról leesett: %1</translation>
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
    <message>
        <source>do not pot %1</source>
        <translation>%1 ne essen lyukba</translation>
    </message>
    <message>
        <source>pot %1</source>
        <translation>%1 lyukba</translation>
    </message>
    <message>
        <source>do not pot %1 in the %2</source>
        <translation>%1 ne essen ebbe a lyukba: %2</translation>
    </message>
    <message>
        <source>pot %1 in the %2</source>
        <translation>%1 lyukba: %2</translation>
    </message>
    <message>
        <source>do not hit %1 first</source>
        <translation>az első érintés ne %1 legyen</translation>
    </message>
    <message>
        <source>hit %1 first</source>
        <translation>az első érintés: %1</translation>
    </message>
    <message>
        <source>scratch</source>
        <translation>a fehér lyukba esik</translation>
    </message>
    <message>
        <source>no scratch</source>
        <translation>a fehér nem esik lyukba</translation>
    </message>
    <message>
        <source>%1 ends outside the region</source>
        <translation>%1 a területen kívül áll meg</translation>
    </message>
    <message>
        <source>%1 ends inside the region</source>
        <translation>%1 a területen belül áll meg</translation>
    </message>
    <message>
        <source>%1 does not touch at most %n cushion(s)</source>
        <translation>%1 nem legfeljebb %n mantinelt érint</translation>
    </message>
    <message>
        <source>%1 touches at most %n cushion(s)</source>
        <translation>%1 legfeljebb %n mantinelt érint</translation>
    </message>
    <message>
        <source>%1 does not touch at least %n cushion(s)</source>
        <translation>%1 nem legalább %n mantinelt érint</translation>
    </message>
    <message>
        <source>%1 touches at least %n cushion(s)</source>
        <translation>%1 legalább %n mantinelt érint</translation>
    </message>
    <message>
        <source>%1 does not touch %n cushion(s)</source>
        <translation>%1 nem pontosan %n mantinelt érint</translation>
    </message>
    <message>
        <source>%1 touches %n cushion(s)</source>
        <translation>%1 pontosan %n mantinelt érint</translation>
    </message>
    <message>
        <source>any shot</source>
        <translation>bármilyen ütés</translation>
    </message>
    <message>
        <source>, </source>
        <translation>, </translation>
    </message>
    <message>
        <source>ghost ball</source>
        <translation>szellemgolyó</translation>
    </message>
    <message>
        <source>aim line</source>
        <translation>célzóvonal</translation>
    </message>
    <message>
        <source>left</source>
        <translation>balra</translation>
    </message>
    <message>
        <source>right</source>
        <translation>jobbra</translation>
    </message>
    <message>
        <source>cut %1 %2, ball fraction %3</source>
        <translation>vágás %1 %2, golyóhányad %3</translation>
    </message>
    <message>
        <source>Arrows: 1 N·s = %1 m; momenta p* in the centre-of-mass frame</source>
        <translation>Nyilak: 1 N·s = %1 m; a p* lendületek a tömegközépponti rendszerben</translation>
    </message>
    <message>
        <source>p* %1 = %2 N·s</source>
        <translation>p* %1 = %2 N·s</translation>
    </message>
    <message>
        <source>p*′ %1 = %2 N·s</source>
        <translation>p*′ %1 = %2 N·s</translation>
    </message>
    <message>
        <source>Δp %1 = J = %2 N·s</source>
        <translation>Δp %1 = J = %2 N·s</translation>
    </message>
    <message>
        <source>Δp %1 = −J = %2 N·s</source>
        <translation>Δp %1 = −J = %2 N·s</translation>
    </message>
    <message>
        <source>centre of mass</source>
        <translation>tömegközéppont</translation>
    </message>
    <message>
        <source>V = %1 m/s</source>
        <translation>V = %1 m/s</translation>
    </message>
    <message>
        <source>%1, seen from the centre of mass</source>
        <translation>%1, a tömegközéppontból nézve</translation>
    </message>
    <message>
        <source>Centre-of-mass frame: paths within %1 s of the event</source>
        <translation>Tömegközépponti rendszer: a pályák az esemény előtti és utáni %1 s-ban</translation>
    </message>
    <message>
        <source>%1.
Export the events computed so far?</source>
        <translation>%1.
Exportálja az eddig kiszámolt eseményeket?</translation>
    </message>
    <message>
        <source>&amp;Copy Shot Code</source>
        <translation>Lökéskód &amp;másolása</translation>
    </message>
    <message>
        <source>Copy the whole setup as one line of text (cuelab:1:...) to share: anyone pastes it into CueLab, or passes it to cuelab-cli, and gets the same shot</source>
        <translation>Az egész felállás másolása egyetlen szövegsorként (cuelab:1:...) megosztáshoz: aki beilleszti a CueLabbe vagy átadja a cuelab-cli-nek, ugyanazt a lökést kapja</translation>
    </message>
    <message numerus="yes">
        <source>Shot code copied: %n character(s)</source>
        <translation>
            <numerusform>Lökéskód másolva: %n karakter</numerusform>
        </translation>
    </message>
    <message>
        <source>&amp;Paste Shot Code</source>
        <translation>Lökéskód &amp;beillesztése</translation>
    </message>
    <message>
        <source>Open the shot code on the clipboard as a new setup</source>
        <translation>A vágólapon lévő lökéskód megnyitása új felállásként</translation>
    </message>
    <message>
        <source>Paste Shot Code</source>
        <translation>Lökéskód beillesztése</translation>
    </message>
    <message>
        <source>The clipboard holds no shot code. A shot code is one line beginning with &quot;cuelab:&quot;, as Edit › Copy Shot Code makes it.</source>
        <translation>A vágólapon nincs lökéskód. A lökéskód egyetlen, „cuelab:” kezdetű sor, amilyet a Szerkesztés › Lökéskód másolása készít.</translation>
    </message>
    <message>
        <source>HD, 1280 × 720</source>
        <translation>HD, 1280 × 720</translation>
    </message>
    <message>
        <source>Full HD, 1920 × 1080</source>
        <translation>Full HD, 1920 × 1080</translation>
    </message>
    <message>
        <source>As the view, %1 × %2</source>
        <translation>Mint a nézet, %1 × %2</translation>
    </message>
    <message>
        <source>Other size</source>
        <translation>Más méret</translation>
    </message>
    <message>
        <source>The video&apos;s size in pixels</source>
        <translation>A videó mérete képpontban</translation>
    </message>
    <message>
        <source>The whole table from above</source>
        <translation>Az egész asztal felülről</translation>
    </message>
    <message>
        <source>The view&apos;s camera</source>
        <translation>A nézet kamerája</translation>
    </message>
    <message>
        <source>From above, the table fills the video whatever its size; the view&apos;s camera keeps the angle and the zoom you set</source>
        <translation>Felülről az asztal bármilyen méretnél kitölti a videót; a nézet kamerája megtartja a beállított szöget és nagyítást</translation>
    </message>
    <message>
        <source>The view&apos;s overlays, arrows and labels as they are now, with the time on every frame.</source>
        <translation>A nézet rétegei, nyilai és feliratai a mostani állapotukban, minden képkockán az idővel.</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Méret</translation>
    </message>
    <message>
        <source>Camera</source>
        <translation>Kamera</translation>
    </message>
    <message>
        <source>A printable report: the diagram, the lesson&apos;s notes, the shot and physics, the outcome, the questions with the guesses and scores, the key collision derived, the event table, the plots</source>
        <translation>Nyomtatható jelentés: az ábra, a lecke jegyzetei, a lövés és a fizika, a kimenetel, a kérdések a tippekkel és a pontszámokkal, a kulcsütközés levezetése, az eseménytáblázat, a grafikonok</translation>
    </message>
    <message>
        <source>dots: the recorded samples of %1, each in its ball&apos;s path colour</source>
        <translation>pontok: %1 felvett mintái, mindegyik a golyója pályájának színében</translation>
    </message>
    <message>
        <source>Export Residuals</source>
        <translation>Eltérések exportálása</translation>
    </message>
    <message>
        <source>CSV (*.csv)</source>
        <translation>CSV (*.csv)</translation>
    </message>
    <message>
        <source>Wrote the residuals to %1</source>
        <translation>Az eltérések kiírva ide: %1</translation>
    </message>
    <message>
        <source>Export Fitted Setup</source>
        <translation>Az illesztett beállítás exportálása</translation>
    </message>
    <message>
        <source>CueLab setups (*.json)</source>
        <translation>CueLab-beállítások (*.json)</translation>
    </message>
    <message>
        <source>Wrote the setup to %1</source>
        <translation>A beállítás kiírva ide: %1</translation>
    </message>
    <message>
        <source>table total</source>
        <translation>az asztal összesen</translation>
    </message>
    <message>
        <source>Predictions</source>
        <translation>Jóslatok</translation>
    </message>
    <message>
        <source>Mean score %1 over %2 of %3 questions answered.</source>
        <translation>Átlagos pontszám: %1 (%3 kérdésből %2 megválaszolva).</translation>
    </message>
    <message>
        <source>No question answered yet: %1 to ask.</source>
        <translation>Még nincs megválaszolt kérdés: %1 kérdés vár.</translation>
    </message>
    <message>
        <source>guess</source>
        <translation>tipp</translation>
    </message>
    <message>
        <source>went</source>
        <translation>ment</translation>
    </message>
    <message>
        <source>error</source>
        <translation>eltérés</translation>
    </message>
    <message>
        <source>score</source>
        <translation>pontszám</translation>
    </message>
    <message>
        <source>Question %1: %2</source>
        <translation>%1. kérdés: %2</translation>
    </message>
    <message>
        <source>The shot stops before %1 at %2 s</source>
        <translation>A lövés megáll ez előtt: %1, %2 s-nál</translation>
    </message>
    <message>
        <source>score %1</source>
        <translation>pontszám: %1</translation>
    </message>
    <message>
        <source>not answered</source>
        <translation>nincs megválaszolva</translation>
    </message>
</context>
<context>
    <name>cuelab::AimControl</name>
    <message>
        <source>The object ball to aim at: the cut angle then sets the heading</source>
        <translation>A célgolyó, amelyre célzunk: a vágási szög ebből adja meg az irányt</translation>
    </message>
    <message>
        <source>Cut angle in degrees between the cue line and the line of centres at contact: 0° a full (straight) hit, 30° a half-ball hit; the straight cue line, before squirt and swerve</source>
        <translation>Vágási szög fokban a dákó vonala és a középpontokat összekötő egyenes között az érintkezéskor: 0° telitalálat (egyenes lökés), 30° fél golyós találat; az egyenes dákóvonal szerint, a kilökődés és az ívelés előtt</translation>
    </message>
    <message>
        <source>left</source>
        <translation>balra</translation>
    </message>
    <message>
        <source>right</source>
        <translation>jobbra</translation>
    </message>
    <message>
        <source>Which way the object ball is cut, seen along the cue line</source>
        <translation>Merre vágjuk a célgolyót, a dákó vonala mentén nézve</translation>
    </message>
    <message>
        <source>The struck ball&apos;s first contact in the simulated shot: the cut angle (degrees) between its path and the line of centres, and the ball fraction 1 − sin(cut), 1 full, 0.5 half ball</source>
        <translation>A megütött golyó első érintkezése a szimulált lökésben: a pályája és a középpontokat összekötő egyenes közti vágási szög (fok) és a golyóhányad, 1 − sin(vágás): 1 teli, 0,5 fél golyó</translation>
    </message>
    <message>
        <source>misses</source>
        <translation>elmegy mellette</translation>
    </message>
    <message>
        <source>First contact: none</source>
        <translation>Első érintkezés: nincs</translation>
    </message>
    <message>
        <source>straight</source>
        <translation>egyenesen</translation>
    </message>
    <message>
        <source>First contact: %1, cut %2 %3, ball fraction %4</source>
        <translation>Első érintkezés: %1, vágás %2 %3, golyóhányad %4</translation>
    </message>
    <message>
        <source>Aim at %1, cut %2 %3</source>
        <translation>Célzás a(z) %1 golyóra, vágás %2 %3</translation>
    </message>
</context>
<context>
    <name>cuelab::AimDrag</name>
    <message>
        <source>The cue: drag across it to turn it (the heading), along it to pull back for more speed or push forward for less. Ctrl+Left/Right turns it by 0.1°, Ctrl+Up/Down changes the speed by 0.1 m/s (with Shift ten times as much, with Alt a tenth).</source>
        <translation>A dákó: keresztben húzva elfordul (az irány), hosszában hátrahúzva gyorsabb, előretolva lassabb lesz. Ctrl+Bal/Jobb 0,1°-kal fordítja, Ctrl+Fel/Le 0,1 m/s-mal változtatja a sebességet (Shifttel tízszer annyival, Alttal egy tizedével).</translation>
    </message>
    <message>
        <source>The ghost ball: where the struck ball meets the first object ball. Drag it to aim: the cue line goes through its centre.</source>
        <translation>A szellemgolyó: itt éri el a meglökött golyó az első tárgygolyót. Húzza a célzáshoz: a dákó vonala a középpontján megy át.</translation>
    </message>
    <message>
        <source>Where the cue tip meets the ball: drag it for side (left, right) and height (follow above the centre, draw below it).</source>
        <translation>Itt éri a dákóvég a golyót: húzza az oldalirányhoz (balra, jobbra) és a magassághoz (a közép fölött utánfutó, alatta visszahúzó ütés).</translation>
    </message>
    <message>
        <source>heading %1°</source>
        <translation>irány %1°</translation>
    </message>
    <message>
        <source>cue speed %1 m/s</source>
        <translation>dákósebesség %1 m/s</translation>
    </message>
    <message>
        <source>tip: side %1 R, height %2 R</source>
        <translation>dákóvég: oldal %1 R, magasság %2 R</translation>
    </message>
    <message>
        <source>left</source>
        <translation>balra</translation>
    </message>
    <message>
        <source>right</source>
        <translation>jobbra</translation>
    </message>
    <message>
        <source>cut %1° %2, ball fraction %3</source>
        <translation>vágás %1° %2, golyóhányad %3</translation>
    </message>
    <message>
        <source>no object ball hit</source>
        <translation>nem talál el tárgygolyót</translation>
    </message>
    <message>
        <source>ball speed %1 m/s</source>
        <translation>golyósebesség %1 m/s</translation>
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
legal, scores, point — the rules of the setup&apos;s game: no foul; the striker plays on; a three-cushion point
!TERM — the term does not hold</source>
        <translation>Mit kell tennie az ütésnek; a feltételeket vessző választja el, mindnek teljesülnie kell:
pot:BALL vagy pot:BALL@POCKET — a golyó lyukba esik (abba a lyukba)
first:BALL — a megütött golyó először a BALL golyót találja el
no-scratch — a megütött golyó az asztalon marad
in:BALL@X0:Y0:X1:Y1 — a golyó abban a téglalapban áll meg (m)
cushions:BALL=N (vagy &lt;=N, &gt;=N) — a golyó mantinelérintései, a lyukpofákkal együtt
legal, scores, point — a beállított játék szabályai: nincs szabálytalanság; a játékos folytatja; háromfalas pont
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
        <source>Tolerance of this shot</source>
        <translation>Az ütés tűrése</translation>
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
    <message>
        <source>Tolerance</source>
        <translation>Tűrés</translation>
    </message>
    <message>
        <source>How far heading, speed, elevation and the tip offsets may miss</source>
        <translation>Mennyit téveszthet az irány, a sebesség, a dőlés és a dákóvég helye</translation>
    </message>
    <message>
        <source>The outcome of every tip offset, or of any two parameters</source>
        <translation>Minden dákóvég-hely, vagy bármely két paraméter minden értékének eredménye</translation>
    </message>
    <message>
        <source>Odds</source>
        <translation>Esély</translation>
    </message>
    <message>
        <source>How often the shot meets the goal under a player&apos;s execution noise</source>
        <translation>Milyen gyakran teljesíti a lökés a célt a játékos kivitelezési szórásával</translation>
    </message>
    <message>
        <source>Find shots</source>
        <translation>Lökések keresése</translation>
    </message>
    <message>
        <source>The strikes that meet the goal most often for the chosen player</source>
        <translation>A választott játékosnak a célt leggyakrabban teljesítő lökések</translation>
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
    <message>
        <source>Left: each ball&apos;s momentum m·v (N s) drawn tip to tail, before and after, with their total (dashed); in the centre-of-mass frame the chain closes on itself. Right: kinetic energy (J) before and after, translation (solid) and rotation (light), and what was lost (hatched): to the collision, and to the cloth since each ball&apos;s previous event.</source>
        <translation>Balra: minden golyó m·v lendülete (N s) egymás után fűzve, előtte és utána, az összegükkel (szaggatott); a tömegközépponti rendszerben a lánc önmagába zárul. Jobbra: a mozgási energia (J) előtte és utána, haladó (telt) és forgó (halvány), valamint ami elveszett (vonalkázott): az ütközésben, és a posztón minden golyó előző eseménye óta.</translation>
    </message>
    <message>
        <source>Momentum, centre-of-mass frame (N s)</source>
        <translation>Lendület, tömegközépponti rendszer (N s)</translation>
    </message>
    <message>
        <source>lost to the collision</source>
        <translation>az ütközésben elveszett</translation>
    </message>
    <message>
        <source>lost to the cloth since the previous event</source>
        <translation>a posztón elveszett az előző esemény óta</translation>
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
    <message>
        <source>frictionless</source>
        <translation>súrlódásmentes</translation>
    </message>
    <message>
        <source>frictional</source>
        <translation>súrlódásos</translation>
    </message>
    <message>
        <source>mirror</source>
        <translation>tükrözés</translation>
    </message>
    <message>
        <source>airborne</source>
        <translation>repül</translation>
    </message>
    <message>
        <source>off-table</source>
        <translation>asztalon kívül</translation>
    </message>
    <message>
        <source>ball-table</source>
        <translation>golyó–asztal</translation>
    </message>
    <message>
        <source>ball-off-table</source>
        <translation>kirepülés az asztalról</translation>
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
    <message>
        <source>Shared shot</source>
        <translation>Megosztott lökés</translation>
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
    <message>
        <source>Time of impact</source>
        <translation>Az ütközés időpontja</translation>
    </message>
    <message>
        <source>Momenta and energy</source>
        <translation>Lendületek és energia</translation>
    </message>
    <message>
        <source>Deriving event #%1… (its held group is found by running the shot again up to it)</source>
        <translation>A #%1 esemény levezetése… (tartott csoportját a lökés eddig az eseményig való újrafuttatása adja)</translation>
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
    <name>cuelab::GameControl</name>
    <message>
        <source>The game whose rules judge the shot: the Outcome dock then says whether it is legal or a foul, and why (docs/rules.md)</source>
        <translation>A játék, amelynek szabályai a lökést megítélik: az Eredmény panel ekkor megmondja, hogy szabályos-e vagy szabálytalan, és miért (docs/rules.md)</translation>
    </message>
    <message>
        <source>No rules</source>
        <translation>Nincs szabály</translation>
    </message>
    <message>
        <source>Snooker</source>
        <translation>Snooker</translation>
    </message>
    <message>
        <source>Three-cushion</source>
        <translation>Háromfalas</translation>
    </message>
    <message>
        <source>The striker&apos;s group: open table, solids (1-7) or stripes (9-15)</source>
        <translation>A játékos csoportja: nyitott asztal, teli (1–7) vagy csíkos (9–15) golyók</translation>
    </message>
    <message>
        <source>Open table</source>
        <translation>Nyitott asztal</translation>
    </message>
    <message>
        <source>Solids</source>
        <translation>Teli golyók</translation>
    </message>
    <message>
        <source>Stripes</source>
        <translation>Csíkos golyók</translation>
    </message>
    <message>
        <source>The ball on: a red, any colour (after a red), or a named colour</source>
        <translation>A soron lévő golyó: piros, bármely színes (piros után) vagy egy megnevezett színes</translation>
    </message>
    <message>
        <source>Red on</source>
        <translation>Piros van soron</translation>
    </message>
    <message>
        <source>Colour on</source>
        <translation>Színes van soron</translation>
    </message>
    <message>
        <source>Yellow on</source>
        <translation>Sárga van soron</translation>
    </message>
    <message>
        <source>Green on</source>
        <translation>Zöld van soron</translation>
    </message>
    <message>
        <source>Brown on</source>
        <translation>Barna van soron</translation>
    </message>
    <message>
        <source>Blue on</source>
        <translation>Kék van soron</translation>
    </message>
    <message>
        <source>Pink on</source>
        <translation>Rózsaszín van soron</translation>
    </message>
    <message>
        <source>Black on</source>
        <translation>Fekete van soron</translation>
    </message>
    <message>
        <source>Judge the shot by the rules of %1</source>
        <translation>A lökés megítélése a(z) %1 szabályai szerint</translation>
    </message>
    <message>
        <source>Judge the shot by no rules</source>
        <translation>A lökés megítélése szabályok nélkül</translation>
    </message>
    <message>
        <source>Set the striker&apos;s group to %1</source>
        <translation>A játékos csoportja: %1</translation>
    </message>
    <message>
        <source>Set the ball on: %1</source>
        <translation>Soron lévő golyó: %1</translation>
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
    <message>
        <source>left</source>
        <translation>balra</translation>
    </message>
    <message>
        <source>right</source>
        <translation>jobbra</translation>
    </message>
    <message>
        <source>straight</source>
        <translation>egyenesen</translation>
    </message>
    <message>
        <source>Aim</source>
        <translation>Célzás</translation>
    </message>
    <message>
        <source>Cut angle</source>
        <translation>Vágási szög</translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Angle in degrees between the first ball&apos;s path and the line of centres at contact: 0° full hit, 30° half ball; left or right: where the other ball goes, seen along the path</source>
        <translation>Az első golyó pályája és a középpontokat összekötő egyenes közti szög fokban az érintkezéskor: 0° telitalálat, 30° fél golyó; balra vagy jobbra: merre megy a másik golyó, a pálya mentén nézve</translation>
    </message>
    <message>
        <source>Ball fraction</source>
        <translation>Golyóhányad</translation>
    </message>
    <message>
        <source>1 − sin(cut angle): the share of the other ball the first covers along its path (1 full, 0.5 half ball, 0 a graze)</source>
        <translation>1 − sin(vágási szög): a másik golyó mekkora részét takarja az első a pályája mentén (1 teli, 0,5 fél golyó, 0 súrolás)</translation>
    </message>
    <message>
        <source>Ghost ball</source>
        <translation>Szellemgolyó</translation>
    </message>
    <message>
        <source>Where the first ball&apos;s centre is at contact (m): aim at it</source>
        <translation>Ahol az első golyó középpontja az érintkezéskor van (m): erre kell célozni</translation>
    </message>
    <message>
        <source>Contact on first ball</source>
        <translation>Érintkezés az első golyón</translation>
    </message>
    <message>
        <source>Where on the first ball the contact lies: degrees from its path, counter-clockwise positive</source>
        <translation>Hol van az érintkezés az első golyón: fok a pályájától mérve, az óramutatóval ellentétesen pozitív</translation>
    </message>
    <message>
        <source>Contact on second ball</source>
        <translation>Érintkezés a második golyón</translation>
    </message>
    <message>
        <source>Where on the second ball the contact lies: degrees from the first ball&apos;s path, counter-clockwise positive</source>
        <translation>Hol van az érintkezés a második golyón: fok az első golyó pályájától mérve, az óramutatóval ellentétesen pozitív</translation>
    </message>
    <message>
        <source>Lost to the cloth</source>
        <translation>A posztón elveszett</translation>
    </message>
    <message>
        <source>Kinetic energy (J) the cloth took from these balls since each one&apos;s previous event</source>
        <translation>A mozgási energia (J), amelyet a posztó elvett ezektől a golyóktól, mindegyik előző eseménye óta</translation>
    </message>
    <message>
        <source>Centre-of-mass frame</source>
        <translation>Tömegközépponti rendszer</translation>
    </message>
    <message>
        <source>The pair&apos;s centre of mass moves at V = (m_a v_a + m_b v_b) / (m_a + m_b) (m/s); seen from it the momenta p* = m (v − V) are equal and opposite</source>
        <translation>A golyópár tömegközéppontja V = (m_a v_a + m_b v_b) / (m_a + m_b) sebességgel mozog (m/s); onnan nézve a p* = m (v − V) lendületek egyenlő nagyságúak és ellentétesek</translation>
    </message>
    <message>
        <source>p* %1 before</source>
        <translation>p* %1 előtte</translation>
    </message>
    <message>
        <source>p* %1 after</source>
        <translation>p* %1 utána</translation>
    </message>
    <message>
        <source>Height</source>
        <translation>Magasság</translation>
    </message>
    <message>
        <source>Height of the centre above its resting height (mm); 0 on the cloth</source>
        <translation>A középpont magassága a nyugalmi magassága fölött (mm); a posztón 0</translation>
    </message>
    <message>
        <source>Vertical speed</source>
        <translation>Függőleges sebesség</translation>
    </message>
    <message>
        <source>Vertical velocity vz (m/s), positive upwards; in flight it falls by g t</source>
        <translation>A függőleges sebesség, vz (m/s), felfelé pozitív; repülés közben g t-vel csökken</translation>
    </message>
</context>
<context>
    <name>cuelab::LaunchReadout</name>
    <message>
        <source>The struck ball just after the cue strike: its speed (m/s), its topspin (+) or backspin (−) about the axis across its path and its side spin (counter-clockwise + seen from above), in rad/s</source>
        <translation>A megütött golyó közvetlenül a lökés után: a sebessége (m/s), a pályájára merőleges tengely körüli felső (+) vagy hátsó (−) pörgése és az oldalpörgése (felülről nézve az óramutatóval ellentétesen +), rad/s-ban</translation>
    </message>
    <message>
        <source>ball %1, topspin %2, side spin %3</source>
        <translation>golyó %1, felső pörgés %2, oldalpörgés %3</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>rad/s</source>
        <translation>rad/s</translation>
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
    <message>
        <source>&amp;Cancel Simulation</source>
        <translation>A szimuláció &amp;leállítása</translation>
    </message>
    <message>
        <source>Stop the running simulation; the events computed so far stay, marked as a partial result</source>
        <translation>Leállítja a futó szimulációt; az eddig kiszámolt események megmaradnak, részeredményként jelölve</translation>
    </message>
    <message>
        <source>Opened the shot code as %1</source>
        <translation>A lökéskód megnyitva ezen a néven: %1</translation>
    </message>
    <message numerus="yes">
        <source>%n event(s) before the question</source>
        <translation>
            <numerusform>%n esemény a kérdés előtt</numerusform>
        </translation>
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
        <source>Computer tournaments (FastFiz)</source>
        <translation>Számítógépes versenyek (FastFiz)</translation>
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
        <source>How the player&apos;s strike scatters: normal errors of these standard deviations on every strike parameter (FastFiz&apos;s model). Computer tournaments: the noise of the computational pool tournaments played on FastFiz, a little steadier than a club player and looser than a professional; all three are explained in docs/analysis.md</source>
        <translation>Mennyire szór a játékos ütése: ekkora szórású normális hibák minden ütésparaméteren (a FastFiz modellje). Számítógépes versenyek: a FastFizen játszott számítógépes pooltornák szórása, valamivel egyenletesebb egy klubjátékosénál és lazább egy profiénál; mindhárom magyarázata a docs/analysis.md-ben</translation>
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
        <source>%1. %2</source>
        <translation>%1. %2</translation>
    </message>
    <message>
        <source> (#%1)</source>
        <translation> (#%1)</translation>
    </message>
    <message>
        <source>Verdict: legal</source>
        <translation>Ítélet: szabályos</translation>
    </message>
    <message>
        <source>Verdict: foul</source>
        <translation>Ítélet: szabálytalanság</translation>
    </message>
    <message>
        <source>The rules of the setup&apos;s game on this shot; double-click to go to the event that decides it</source>
        <translation>A beállított játék szabályainak ítélete erről a lökésről; dupla kattintással a döntő eseményre ugrik</translation>
    </message>
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
        <translation>Vége</translation>
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
    <message>
        <source>%1. So far: %2</source>
        <translation>%1. Eddig: %2</translation>
    </message>
    <message>
        <source>%1; the outcome shows after the reveal</source>
        <translation>%1; a kimenetel a felfedés után látható</translation>
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
        <translation>Összes</translation>
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
    <message>
        <source>Momentum |p|, px, py (N s)</source>
        <translation>Lendület |p|, px, py (N s)</translation>
    </message>
    <message>
        <source>Energy parts and losses, whole table (J)</source>
        <translation>Energiarészek és veszteségek, az egész asztal (J)</translation>
    </message>
    <message>
        <source> |p|</source>
        <translation> |p|</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source> py</source>
        <translation> py</translation>
    </message>
    <message>
        <source>|total p|</source>
        <translation>|teljes p|</translation>
    </message>
    <message>
        <source>translation</source>
        <translation>haladó</translation>
    </message>
    <message>
        <source>rotation</source>
        <translation>forgó</translation>
    </message>
    <message>
        <source>lost to collisions and pockets</source>
        <translation>ütközésekben és zsebekben elveszett</translation>
    </message>
    <message>
        <source>lost to the cloth</source>
        <translation>a posztón elveszett</translation>
    </message>
    <message>
        <source>Whole table</source>
        <translation>Az egész asztal</translation>
    </message>
    <message>
        <source>Plo&amp;t</source>
        <translation>Áb&amp;ra</translation>
    </message>
    <message>
        <source>Height z (m) and vertical speed vz (m/s)</source>
        <translation>Magasság, z (m) és függőleges sebesség, vz (m/s)</translation>
    </message>
    <message>
        <source>What to plot against time (s). Slip speed: the speed of the ball&apos;s contact point on the cloth (m/s), zero while it rolls. Energy: translational, rotational and total (J). Momentum: m v in N s, its length and components; for all balls each ball&apos;s |p| and the length of the total. Energy parts: the whole table&apos;s translation and rotation, what the events (collisions, pockets) and the cloth have taken so far, and the energy put in (J), which the four add up to. Height: how far the ball&apos;s centre is above its resting height (m), 0 on the cloth, and its vertical speed (m/s, + up): each flight is a parabola, each bounce a jump of vz.</source>
        <translation>Mit ábrázoljon az idő (s) függvényében. Csúszási sebesség: a golyó posztóval érintkező pontjának sebessége (m/s), gördülés közben nulla. Energia: haladó, forgó és teljes (J). Lendület: m v N s-ban, a nagysága és az összetevői; minden golyónál az egyes golyók |p| értéke és az összeg nagysága. Energiarészek: az egész asztal haladó és forgó energiája, amit eddig az események (ütközések, zsebek) és a posztó elvettek, valamint a bevitt energia (J), amelyet a négy együtt kiad. Magasság: a golyó középpontja mennyivel van a nyugalmi magassága fölött (m), a posztón 0, és a függőleges sebessége (m/s, felfelé +): minden repülés egy parabola, minden pattanás egy ugrás vz-ben.</translation>
    </message>
    <message>
        <source> z</source>
        <translation> z</translation>
    </message>
    <message>
        <source> vz</source>
        <translation> vz</translation>
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
    <message>
        <source>%1 (shown after the reveal)</source>
        <translation>%1 (a felfedés után látható)</translation>
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
    <message>
        <source>Aiming is locked until you reveal the answer: a changed shot would give it away. Reveal, or stop Predict, to aim again.</source>
        <translation>A célzás a válasz felfedéséig zárolva van: a megváltoztatott lövés elárulná a választ. Fedje fel, vagy állítsa le a Jóslást, hogy újra célozhasson.</translation>
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
    <message>
        <source>Distance (cm) between each recorded sample and the simulated ball at the sample&apos;s time (s), one line per ball: where the model and the recording part. Thin grey lines: the simulation&apos;s collisions</source>
        <translation>Az egyes felvett minták távolsága (cm) a szimulált golyótól a minta idejében (s), golyónként egy vonal: itt válik el a modell és a felvétel. Vékony szürke vonalak: a szimuláció ütközései</translation>
    </message>
    <message>
        <source>How much of the fit&apos;s work is done</source>
        <translation>Az illesztés munkájának elvégzett része</translation>
    </message>
    <message>
        <source>Residuals (CSV)…</source>
        <translation>Eltérések (CSV)…</translation>
    </message>
    <message>
        <source>Write every recorded sample with the simulated position at its time and their distance (m) as CSV</source>
        <translation>Minden felvett minta kiírása CSV-be a szimulált helyzettel az idejében és a távolságukkal (m)</translation>
    </message>
    <message>
        <source>Fitted Setup…</source>
        <translation>Illesztett beállítás…</translation>
    </message>
    <message>
        <source>Save the setup as it is now (after a fit: the fitted strike and cloth) as a setup file</source>
        <translation>A beállítás mentése a mostani állapotában (illesztés után: az illesztett ütéssel és posztóval) beállításfájlként</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportálás</translation>
    </message>
    <message>
        <source>Export the residuals (CSV) or the fitted setup</source>
        <translation>Az eltérések (CSV) vagy az illesztett beállítás exportálása</translation>
    </message>
</context>
<context>
    <name>cuelab::RunState</name>
    <message>
        <source>Simulating… %1 events, t = %2</source>
        <translation>Szimuláció… %1 esemény, t = %2</translation>
    </message>
    <message>
        <source>Simulating… %1 events so far, t = %2</source>
        <translation>Szimuláció… eddig %1 esemény, t = %2</translation>
    </message>
    <message>
        <source>Stopped at t = %1 (cancelled after %2 events): a partial result</source>
        <translation>Leállítva t = %1-nál (%2 esemény után megszakítva): részeredmény</translation>
    </message>
    <message>
        <source>Cut short at t = %1 (event limit reached): a partial result</source>
        <translation>Idő előtt leállt t = %1-nál (elérte az eseménykorlátot): részeredmény</translation>
    </message>
    <message>
        <source>Until the reveal: the shot up to t = %1</source>
        <translation>A felfedésig: a lövés t = %1 pillanatig</translation>
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
    <message>
        <source>Predict (while a question waits)</source>
        <translation>Jóslás (amíg egy kérdés vár)</translation>
    </message>
    <message>
        <source>Aim: turn the cue (at t = 0)</source>
        <translation>Célzás: a dákó elfordítása (t = 0-nál)</translation>
    </message>
    <message>
        <source>Drag across the cue, or drag the ghost ball</source>
        <translation>A dákó keresztirányú húzása vagy a szellemgolyó húzása</translation>
    </message>
    <message>
        <source>Cue speed</source>
        <translation>Dákósebesség</translation>
    </message>
    <message>
        <source>Drag along the cue: back for faster, forward for slower</source>
        <translation>A dákó hosszirányú húzása: hátra gyorsabb, előre lassabb</translation>
    </message>
    <message>
        <source>Strike off centre (side, height)</source>
        <translation>Középen kívüli ütés (oldal, magasság)</translation>
    </message>
    <message>
        <source>Drag the tip mark on the ball in the player view (Ctrl+2)</source>
        <translation>A golyón lévő dákóvégjel húzása játékosnézetben (Ctrl+2)</translation>
    </message>
    <message>
        <source>Fine-tune the aim (view focused)</source>
        <translation>A célzás finomhangolása (fókuszban a nézet)</translation>
    </message>
    <message>
        <source>Ctrl+Left/Right: heading ±0.1°; Ctrl+Up/Down: speed ±0.1 m/s; Shift ×10, Alt ×0.1</source>
        <translation>Ctrl+Bal/Jobb: irány ±0,1°; Ctrl+Fel/Le: sebesség ±0,1 m/s; Shift ×10, Alt ×0,1</translation>
    </message>
    <message>
        <source>Give a ball an initial velocity (at t = 0)</source>
        <translation>Kezdősebesség adása egy golyónak (t = 0-nál)</translation>
    </message>
    <message>
        <source>Ctrl + drag from the ball (not the struck ball), or drag the head of its velocity arrow</source>
        <translation>Ctrl + húzás a golyótól (nem a meglökött golyótól), vagy a sebességnyíl hegyének húzása</translation>
    </message>
    <message>
        <source>Say where a ball will go</source>
        <translation>Megadni, merre megy majd egy golyó</translation>
    </message>
    <message>
        <source>Drag from the ringed ball the way it will go; drag again to change it</source>
        <translation>Húzás a bekarikázott golyótól arra, amerre menni fog; újabb húzással módosítható</translation>
    </message>
    <message>
        <source>Say a ball stays</source>
        <translation>Megadni, hogy egy golyó a helyén marad</translation>
    </message>
    <message>
        <source>Click the ringed ball</source>
        <translation>Kattintás a bekarikázott golyóra</translation>
    </message>
    <message>
        <source>Move the camera</source>
        <translation>A kamera mozgatása</translation>
    </message>
    <message>
        <source>Right or middle drag, and the mouse wheel</source>
        <translation>Húzás jobb vagy középső gombbal, és az egérgörgő</translation>
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
    <name>cuelab::ShotFinderSection</name>
    <message>
        <source>Find shots</source>
        <translation>Lökések keresése</translation>
    </message>
    <message>
        <source>The strikes that meet the goal most often for the player of the odds section: direct pots, banks, kicks and combinations, each refined over aim, speed and tip (docs/solve.md).</source>
        <translation>Azok a lökések, amelyek az esélyszakasz játékosánál a leggyakrabban teljesítik a célt: egyenes lökések, falazások, kerülések és kombinációk, mindegyik célzásra, sebességre és dákóvégre finomítva (docs/solve.md).</translation>
    </message>
    <message>
        <source> shots</source>
        <translation> lökés</translation>
    </message>
    <message>
        <source>At most this many shots, each by another route or pocket</source>
        <translation>Legfeljebb ennyi lökés, mindegyik más úton vagy más lyukba</translation>
    </message>
    <message>
        <source>Jumps and massés</source>
        <translation>Ugratások és masszék</translation>
    </message>
    <message>
        <source>Also search the cue&apos;s elevation</source>
        <translation>A dákó emelését is keresi</translation>
    </message>
    <message>
        <source>Pick on the table</source>
        <translation>Kijelölés az asztalon</translation>
    </message>
    <message>
        <source>Make the goal by clicks on the table: a ball to pot, the pocket, then drag a zone where the cue ball should stop</source>
        <translation>A cél összeállítása kattintásokkal az asztalon: a lökendő golyó, a lyuk, majd húzással egy terület, ahol a fehér golyónak meg kell állnia</translation>
    </message>
    <message>
        <source>Click a shot to load its strike (one undo step)</source>
        <translation>Kattintson egy lökésre a betöltéséhez (egy visszavonási lépés)</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Mégse</translation>
    </message>
    <message>
        <source>Click the ball to pot, then its pocket; drag a zone for the cue ball.</source>
        <translation>Kattintson a lökendő golyóra, majd a lyukára; húzzon ki egy területet a fehér golyónak.</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>Megszakítva.</translation>
    </message>
    <message>
        <source>The setup changed since these shots were found; find again.</source>
        <translation>A felállás megváltozott, mióta ezek a lökések megvannak; keressen újra.</translation>
    </message>
    <message>
        <source>Goal: %1</source>
        <translation>Cél: %1</translation>
    </message>
    <message>
        <source>Type a goal above first, e.g. pot:1@pocket-tr,no-scratch.</source>
        <translation>Előbb adjon meg fent egy célt, pl. pot:1@pocket-tr,no-scratch.</translation>
    </message>
    <message>
        <source>Searching…</source>
        <translation>Keresés…</translation>
    </message>
    <message>
        <source>%1. %2: %3 % (%4–%5 %)</source>
        <translation>%1. %2: %3% (%4–%5%)</translation>
    </message>
    <message>
        <source>, into %1</source>
        <translation>, ide: %1</translation>
    </message>
    <message>
        <source>No strike met the goal (%1 simulations, %2 s).</source>
        <translation>Egyik lökés sem teljesítette a célt (%1 szimuláció, %2 s).</translation>
    </message>
    <message>
        <source>%1 simulations in %2 s; each shot&apos;s odds from %3 fresh strikes.</source>
        <translation>%1 szimuláció %2 s alatt; minden lökés esélye %3 új lökésből.</translation>
    </message>
    <message>
        <source>That is the struck ball: click a ball to pot.</source>
        <translation>Ez a megütött golyó: kattintson egy lökendő golyóra.</translation>
    </message>
    <message>
        <source>Click the ball to pot first.</source>
        <translation>Előbb a lökendő golyóra kattintson.</translation>
    </message>
    <message>
        <source>found shot %1</source>
        <translation>%1. talált lökés</translation>
    </message>
    <message>
        <source>Load found shot %1 (%2)</source>
        <translation>A(z) %1. talált lökés betöltése (%2)</translation>
    </message>
    <message>
        <source>That shot is not a legal setup.</source>
        <translation>Ez a lökés nem szabályos felállás.</translation>
    </message>
</context>
<context>
    <name>cuelab::ShotPanel</name>
    <message>
        <source>Game</source>
        <translation>Játék</translation>
    </message>
    <message>
        <source>Strike a ball at t = 0</source>
        <translation>Ütés t = 0-kor</translation>
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
        <translation>Dákósúly</translation>
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
        <translation>Végsúly</translation>
    </message>
    <message>
        <source>Aim at</source>
        <translation>Célzás</translation>
    </message>
</context>
<context>
    <name>cuelab::SimulationOverlay</name>
    <message>
        <source>Cancel</source>
        <translation>Mégse</translation>
    </message>
    <message>
        <source>Stop the simulation: the events computed so far stay, marked as a partial result (Esc)</source>
        <translation>A szimuláció leállítása: az eddig kiszámolt események megmaradnak, részeredményként jelölve (Esc)</translation>
    </message>
</context>
<context>
    <name>cuelab::SimulationRunner</name>
    <message>
        <source>The simulation failed: %1</source>
        <translation>A szimuláció nem sikerült: %1</translation>
    </message>
</context>
<context>
    <name>cuelab::SpoilerCurtain</name>
    <message>
        <source>Hidden until you reveal the answer: this panel would show how the shot goes on.</source>
        <translation>Rejtve, amíg fel nem fedi a választ: ez a panel megmutatná, hogyan folytatódik a lövés.</translation>
    </message>
</context>
<context>
    <name>cuelab::SquirtControl</name>
    <message>
        <source>Squirt</source>
        <translation>Kitérés</translation>
    </message>
    <message>
        <source>Squirt: side english sends the cue ball off the cue line, away from the side of the english, by an angle that grows as the tip&apos;s end mass grows (Alciatore TP A-31). Off: the ball leaves along the cue line.</source>
        <translation>Kitérés (squirt): az oldalpörgetés a dákó vonalától elviszi a fehér golyót, a pörgetéssel ellentétes oldalra, annál nagyobb szögben, minél nagyobb a dákóvég tömege (Alciatore TP A-31). Kikapcsolva: a golyó a dákó vonalában indul.</translation>
    </message>
    <message>
        <source>g</source>
        <translation>g</translation>
    </message>
    <message>
        <source>End mass of the cue tip in grams, the part of the shaft that moves with the tip during the hit (about 5.7 g for a pool cue, a thirtieth of the ball; low-squirt shafts are lighter)</source>
        <translation>A dákóvég végtömege grammban: a szár azon része, amely az ütés alatt a dákóvéggel együtt mozog (pooldákónál kb. 5,7 g, a golyó harmincad része; a kis kitérésű szárak könnyebbek)</translation>
    </message>
    <message>
        <source>Turn squirt on</source>
        <translation>A kitérés bekapcsolása</translation>
    </message>
    <message>
        <source>Turn squirt off</source>
        <translation>A kitérés kikapcsolása</translation>
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
<context>
    <name>cuelab::examples</name>
    <message>
        <source>9-ball safety</source>
        <translation>9-es biztonsági lökés</translation>
    </message>
    <message>
        <source>9-ball under WPA rules (&quot;game&quot;: 9-ball): the 1 is the ball on, close to the top rail with the 9 beyond it, and no pot is on. The player plays safe instead: a soft hit (1 m/s) on the left of the 1 sends it into the top rail (#6) and off the right rail, while the cue ball follows to the top rail and stops with the 9 exactly between it and the 1. Verdict: legal, nothing pocketed, the turn passes. Legal because the cue ball met the ball on first (#3) and a ball reached a cushion after that contact; the opponent now has no straight line to the 1. Play it at 0.45 m/s and the 1 stops short of the rail with no ball touching one after the contact: a foul (no-rail), ball in hand for the opponent.</source>
        <translation>9-es a WPA szabályai szerint (&quot;game&quot;: 9-ball): az 1-es van soron, közel a felső mantinelhez, mögötte a 9-es, és nincs lyukra lökhető golyó. A játékos ezért biztonsági lökést választ: egy lágy lökés (1 m/s) az 1-es bal oldalára a felső mantinelbe küldi az 1-est (#6), majd onnan a jobb mantinelre, a fehér golyó pedig a felső mantinelig követi, és úgy áll meg, hogy a 9-es pontosan közte és az 1-es között van. Ítélet: szabályos, nem esett golyó lyukba, a másik játékos következik. Azért szabályos, mert a fehér golyó először a soron lévő golyót érte el (#3), és az érintkezés után egy golyó mantinelt ért; az ellenfélnek most nincs egyenes útja az 1-eshez. 0,45 m/s-mal lökve az 1-es megáll a mantinel előtt, és az érintkezés után egy golyó sem ér mantinelt: szabálytalanság (no-rail), az ellenfél kézből helyezi a fehér golyót.</translation>
    </message>
    <message>
        <source>Snooker plant, red on</source>
        <translation>Snooker plant, piros van soron</translation>
    </message>
    <message>
        <source>The snooker plant judged by the rules of snooker (&quot;game&quot;: snooker, a red on), with the black on its spot. The cue ball meets red-1 first (#2): a red, so the contact is legal although red-2 is the ball that drops (#7, top-right pocket). Verdict: legal, red-2 potted (+1), the striker plays on (next on a colour). A plant is a legal way to pot a red: the rules ask only that the first ball hit is on and that no ball that is not on goes down. Aim at the black instead (heading -2.6°): the cue ball&apos;s first contact is a ball not on, a foul (wrong-ball-first) worth 7 points to the opponent, the black&apos;s value, more than the minimum of 4.</source>
        <translation>A snooker plant a snooker szabályai szerint megítélve (&quot;game&quot;: snooker, piros van soron), a feketével a helyén. A fehér golyó először a red-1-et éri el (#2): ez piros, tehát az érintkezés szabályos, noha a red-2 esik lyukba (#7, jobb felső lyuk). Ítélet: szabályos, lyukba esett a red-2 (+1), a játékos folytatja (ezután színes golyó van soron). A plant szabályos módja egy piros lyukba juttatásának: a szabály csak azt kéri, hogy az elsőként eltalált golyó soron legyen, és ne essen lyukba soron kívüli golyó. Ha a feketére céloz (irány -2,6°), a fehér golyó először soron kívüli golyót ér el: szabálytalanság (wrong-ball-first), 7 pont az ellenfélnek, a fekete értéke, ami több a 4 pontos minimumnál.</translation>
    </message>
    <message>
        <source>Three-cushion point</source>
        <translation>Háromfalas pont</translation>
    </message>
    <message>
        <source>The three-cushion carom judged by UMB rules (&quot;game&quot;: three-cushion): the struck white is the striker&apos;s ball, the red and the yellow the object balls. Count the white&apos;s own cushions before it meets its second object ball, on the event list: it meets the red (#2), then the right rail (#6), the bottom rail (#8) and the left rail (#12), and then the yellow (#16). Three cushions before the second object ball: verdict, a point, and the striker plays on. The red&apos;s cushions (#4, #10, #14) do not count, nor would any after the yellow. Headings from about 23.4° to 23.7° score; the Three-cushion near miss example moves the yellow onto the white&apos;s path.</source>
        <translation>A háromfalas karambol az UMB szabályai szerint megítélve (&quot;game&quot;: three-cushion): a meglökött fehér a játékos golyója, a piros és a sárga a tárgygolyók. Számolja meg az eseménylistán a fehér saját mantinelérintéseit, mielőtt a második tárgygolyót eléri: eltalálja a pirosat (#2), majd a jobb mantinelt (#6), az alsót (#8) és a bal mantinelt (#12), aztán a sárgát (#16). Három mantinel a második tárgygolyó előtt: az ítélet pont, és a játékos folytatja. A piros mantinelérintései (#4, #10, #14) nem számítanak, ahogy a sárga utániak sem számítanának. Nagyjából 23,4° és 23,7° közötti irányok adnak pontot; a Háromfalas: majdnem pont példa a sárgát a fehér útjába teszi.</translation>
    </message>
    <message>
        <source>Three-cushion near miss</source>
        <translation>Háromfalas: majdnem pont</translation>
    </message>
    <message>
        <source>The three-cushion point&apos;s stroke with the yellow moved onto the white&apos;s path from the bottom rail to the left rail. The white meets the red (#2), the right rail (#6) and the bottom rail (#8), and then the yellow (#12), before it can reach the left rail. Verdict: no point, the turn passes: the white met both object balls, but with only two cushions before the second (UMB: three or more). Only the white&apos;s own cushions before its second object ball count; the red&apos;s (#4, #10) never do.</source>
        <translation>A háromfalas pont lökése, a sárgával a fehérnek az alsó mantineltől a bal mantinel felé vezető útjába helyezve. A fehér eltalálja a pirosat (#2), a jobb mantinelt (#6) és az alsót (#8), majd a sárgát (#12), mielőtt a bal mantinelt elérhetné. Ítélet: nincs pont, a másik játékos következik: a fehér mindkét tárgygolyót elérte, de a második előtt csak két mantinellel (UMB: legalább három kell). Csak a fehér saját mantinelérintései számítanak a második tárgygolyó előtt; a piroséi (#4, #10) sohasem.</translation>
    </message>
    <message>
        <source>8-ball break</source>
        <translation>8-as nyitás</translation>
    </message>
    <message>
        <source>Fifteen balls racked frozen (every neighbour touching) with the 1 on the foot spot, the cue ball on the head spot, a hard centre-ball hit straight at the 1. The impact runs through the frozen rack as a chain of collisions at the same instant, resolved one touching pair at a time, and spreads the balls over the table.</source>
        <translation>Tizenöt golyó szorosan gúlába rakva (minden szomszéd érinti egymást), az 1-es a lábponton, a fehér golyó a fejponton; erős, középre mért lökés egyenesen az 1-esre. Az ütközés ugyanabban a pillanatban ütközések láncaként fut végig az egymáshoz simuló gúlán, amelyet a szimuláció egyszerre egy érintkező párt feloldva követ, és szétszórja a golyókat az asztalon.</translation>
    </message>
    <message>
        <source>9-ball break</source>
        <translation>9-es nyitás</translation>
    </message>
    <message>
        <source>Nine balls in a frozen diamond, the 1 on the foot spot and the 9 in the middle, broken from the side of the head string (a cut break, as many players prefer): the cue ball hits the 1 full in the face at 5.5 m/s cue speed.</source>
        <translation>Kilenc golyó egymáshoz simuló rombuszban, az 1-es a lábponton, a 9-es középen; a nyitás a fejvonal széléről indul (vágott nyitás, ahogy sok játékos szereti): a fehér golyó 5,5 m/s dákósebességgel telibe találja az 1-est.</translation>
    </message>
    <message>
        <source>Draw shot</source>
        <translation>Húzott ütés</translation>
    </message>
    <message>
        <source>The stun shot&apos;s position, struck well below centre (height -0.55) and harder. The cue ball still spins backwards when it meets the 1; after the collision the backspin pulls it back along its path, about 15 cm. More speed or a lower tip draws it further.</source>
        <translation>A stopütés felállása, jóval a közép alatt (magasság -0,55) és erősebben megütve. A fehér golyó még visszafelé pörög, amikor eléri az 1-est; az ütközés után a hátrapörgés visszahúzza a pályáján, körülbelül 15 cm-t. Nagyobb sebesség vagy lejjebb vett dákóvég messzebbre húzza.</translation>
    </message>
    <message>
        <source>Fast graze</source>
        <translation>Gyors súrolás</translation>
    </message>
    <message>
        <source>The 2011 lesson: a hard, very thin hit. The cue ball leaves at 10 m/s and overlaps the 5 by 2 mm of its width; the 5 goes off almost square and drops in the top side pocket. The fixed-step method of the 2011 game (Compare, discrete, 60 Hz with 10 sub-steps) tests the balls every 17 mm of travel, while they overlap for only 15 mm while approaching: it tunnels through the 5 and the cue ball runs on untouched. At 1 ms it finds the hit. Box2D&apos;s continuous collision finds it at 60 Hz, but resolves it with the balls 1.5 mm deep (three of its linear slops), so the 5 leaves at the wrong angle and misses the pocket.</source>
        <translation>A 2011-es lecke: erős, nagyon vékony találat. A fehér golyó 10 m/s-mal indul, és szélességéből 2 mm-rel fedi az 5-öst; az 5-ös majdnem derékszögben indul el, és a felső középső lyukba esik. A 2011-es játék rögzített lépésközű módszere (Összehasonlítás, diszkrét, 60 Hz 10 allépéssel) 17 mm-enként vizsgálja a golyókat, közeledés közben viszont csak 15 mm-en át fedik egymást: a fehér golyó átlép az 5-ösön (alagúthatás), és érintetlenül fut tovább. 1 ms-os lépéssel a módszer megtalálja a találatot. A Box2D folytonos ütközésvizsgálata 60 Hz-en is megtalálja, de úgy oldja fel, hogy a golyók 1,5 mm mélyen egymásba hatolnak (lineáris tűréshatárának háromszorosa), így az 5-ös rossz szögben indul el, és elkerüli a lyukat.</translation>
    </message>
    <message>
        <source>Follow shot</source>
        <translation>Utánfutó ütés</translation>
    </message>
    <message>
        <source>The stun shot&apos;s position, struck above centre (height 0.4, natural roll). The cue ball rolls into the 1; the collision takes its speed but not its topspin, which grips the cloth and drives it forward again until it rolls at 2/7 of its impact speed. It follows the 1 towards the side pocket and stops in front of it.</source>
        <translation>A stopütés felállása, a közép fölött megütve (magasság 0,4, természetes gördülés). A fehér golyó gördülve éri el az 1-est; az ütközés elveszi a sebességét, de a felső pörgetését nem, amely belekap a posztóba, és újra előre hajtja, amíg ütközési sebességének 2/7-ével nem gördül. Követi az 1-est a középső lyuk felé, és előtte megáll.</translation>
    </message>
    <message>
        <source>Half-ball cut (the 30° rule)</source>
        <translation>Félgolyós vágás (a 30°-os szabály)</translation>
    </message>
    <message>
        <source>The cue ball&apos;s centre line passes the object ball&apos;s edge: a half-ball hit, cut angle 30°. The 1 leaves along the line of centres into the top-right corner pocket. Struck with natural roll (tip 0.4 R above centre), the cue ball is deflected from its aim line once it rolls again by the same angle whatever the speed: 33.7° with perfectly elastic balls, 32.3° here with restitution 0.95. That is the 30° rule: a rolling cue ball&apos;s path turns by roughly 30° for every cut between a quarter-ball and a three-quarter-ball hit.</source>
        <translation>A fehér golyó középvonala a célgolyó szélén halad át: félgolyós találat, 30°-os vágási szög. Az 1-es a centrálegyenes mentén a jobb felső sarok lyukába indul. Természetes gördüléssel megütve (a dákóvég 0,4 R-rel a közép fölött) a fehér golyó, amint újra gördül, a sebességtől függetlenül ugyanakkora szöggel tér el a célvonalától: tökéletesen rugalmas golyókkal 33,7°-kal, itt, 0,95-ös ütközési számmal 32,3°-kal. Ez a 30°-os szabály: a gördülő fehér golyó pályája nagyjából 30°-kal fordul el minden vágásnál a negyedgolyós és a háromnegyed-golyós találat között.</translation>
    </message>
    <message>
        <source>Massé around a ball</source>
        <translation>Masszé egy golyó körül</translation>
    </message>
    <message>
        <source>The 2 sits right on the line from the cue ball to the 1: a level stroke at the 1 hits the 2 first. A massé goes around it. The cue is raised 50° and strikes left of centre (side -0.5) at 5.25 m/s, aimed 19.5° below the x axis, some 34° right of the 1. The elevated cue drives the ball down into the cloth as well as forward, and the cloth throws it up: it hops 9 cm high (select the ball-table event at t = 0), bounces at 0.27 s and 0.41 s, each time half as high, and the endless rest of its bounces is summed in closed form, ending at 0.54 s. The cue also tilts the ball&apos;s spin axis, so the slip of its contact point points away from its motion: at every bounce, and then while it slides, the cloth&apos;s friction pushes along that slip and bends the path to the left (towards the english), around the 2 and into the 1, which drops in the top-right pocket. Once the slip is gone the ball rolls straight on: select the slide-to-roll event to read it. Change the heading by a degree and the shot fails: massé is a hard stroke.</source>
        <translation>A 2-es pontosan a fehér golyót az 1-essel összekötő egyenesen áll: egy vízszintes lökés az 1-es felé először a 2-est találja el. Egy masszé megkerüli. A dákó 50°-kal megemelve, a középtől balra (oldal -0,5) 5,25 m/s-mal találja a golyót, 19,5°-kal az x tengely alá célozva, mintegy 34°-kal az 1-estől jobbra. A megemelt dákó nemcsak előre, hanem lefelé, a posztóba is hajtja a golyót, és a posztó feldobja: 9 cm magasra ugrik (jelölje ki a golyó–asztal eseményt t = 0-nál), 0,27 s-nál és 0,41 s-nál pattan, mindig feleakkorát, további végtelen sok pattanásának összegét pedig zárt alakban kapjuk: 0,54 s-nál ér véget. A dákó a golyó forgástengelyét is megdönti, így érintkezési pontjának csúszása a mozgásától elfelé mutat: minden pattanáskor, majd amíg csúszik, a posztó súrlódása e csúszás irányába tol, és balra (az oldalpörgetés felé) hajlítja a pályát, a 2-es körül és bele az 1-esbe, amely a jobb felső lyukba esik. Amint a csúszás megszűnik, a golyó egyenesen gördül tovább: a csúszásból gördülés eseményt kijelölve leolvasható. Egy fokkal más irány, és az ütés nem sikerül: a masszé nehéz ütés.</translation>
    </message>
    <message>
        <source>Jump over a ball</source>
        <translation>Ugratás egy golyó fölött</translation>
    </message>
    <message>
        <source>The 2 blocks the straight line from the cue ball to the 1, 15 cm away. Raise the cue 45° and strike the centre at 4 m/s: the cue drives the ball down into the cloth at 2.22 m/s as well as forward at 2.22 m/s, and the cloth throws it back up at half that, 1.11 m/s (its restitution, 0.5; select the ball-table event at t = 0). It flies a parabola for 2 v_z/g = 0.226 s, 6.3 cm high at the top, and passes over the 2 with about 4 mm to spare (where it crosses the 2 its centre must be more than 2R = 5.7 cm up). It bounces twice more, the endless rest of its bounces summed in closed form, and meets the 1 sliding, full in the face: the 1 rolls into the top-right pocket. The downward stroke also gave the cue ball backspin, so it draws back and meets the 2 after all. Lower the cue to 35° and it hits the 2 first; strike at 5 m/s and it is still in the air, on its second hop, when it meets the 1.</source>
        <translation>A 2-es elzárja az egyenes utat a fehér golyótól az 1-esig, 15 cm-re a fehértől. Emelje a dákót 45°-ra, és lökje a golyó közepét 4 m/s-mal: a dákó 2,22 m/s-mal lefelé, a posztóba hajtja a golyót, és ugyanennyivel előre, a posztó pedig feleekkora, 1,11 m/s sebességgel dobja vissza felfelé (ez a restitúciója, 0,5; jelölje ki a golyó–asztal eseményt t = 0-nál). A golyó 2 v_z/g = 0,226 s-ig repül parabolapályán, a tetején 6,3 cm magasan, és mintegy 4 mm-rel a 2-es fölött halad el (ahol a 2-es fölé ér, középpontjának 2R = 5,7 cm-nél magasabban kell lennie). Még kétszer pattan, további végtelen sok pattanásának összegét zárt alakban kapjuk, majd csúszva, telibe találja az 1-est: az 1-es a jobb felső lyukba gurul. A lefelé irányuló lökés hátrapörgetést is adott a fehérnek, így visszahúzódik, és végül mégis eltalálja a 2-est. 45° helyett 35°-os dákóval előbb a 2-est találja el; 5 m/s-os lökéssel még a levegőben, a második ugrásán találkozik az 1-essel.</translation>
    </message>
    <message>
        <source>Off the table</source>
        <translation>Le az asztalról</translation>
    </message>
    <message>
        <source>A jump shot near a rail. The cue ball is 34 cm from the foot cushion; the cue, raised 45°, strikes its centre at 5 m/s straight at the rail. The cloth throws the ball up at 1.39 m/s (select the ball-table event at t = 0), and 0.175 s later, where the cushion&apos;s nose is, its centre is 9.2 cm above its resting height: its bottom passes far above the nose (3.7 cm up), so it flies over the rail and off the table. That is a ball-off-table event, and the ball is out of play (off-table) from then on. Strike at 3 m/s instead: it comes down 0.17 s later short of the rail, hops three times, meets the cushion on its last little hop and runs back down the table into the 1.</source>
        <translation>Ugratás egy falhoz közel. A fehér golyó 34 cm-re van az alsó (láb felőli) fal gumijától; a 45°-ra emelt dákó 5 m/s-mal, egyenesen a fal felé lökve a közepét találja el. A posztó 1,39 m/s-mal dobja fel a golyót (jelölje ki a golyó–asztal eseményt t = 0-nál), és 0,175 s múlva, a gumi élénél, középpontja 9,2 cm-rel van nyugalmi magassága fölött: alja messze a gumi éle (3,7 cm) fölött halad el, így átrepül a falon, le az asztalról. Ez egy kirepülés az asztalról esemény, és a golyó ettől fogva kiesett a játékból (asztalon kívül). Lökje inkább 3 m/s-mal: 0,17 s múlva a fal előtt ér le, háromszor pattan, utolsó kis ugrásán éri el a gumit, és visszafut az asztalon, bele az 1-esbe.</translation>
    </message>
    <message>
        <source>Newton&apos;s cradle</source>
        <translation>Newton-bölcső</translation>
    </message>
    <message>
        <source>Five balls frozen in a line, hit straight by a stunned cue ball. With perfectly elastic balls (ball-ball restitution 1 in this file) the impulse travels down the line, one touching pair after another at the same instant, and only the last ball leaves, at the cue ball&apos;s speed. It rebounds from the foot rail, comes back into the line, and the cue ball is knocked back in turn. Set the restitution back to 0.95 to see the energy spread along the line instead.</source>
        <translation>Öt egymáshoz simuló golyó egy sorban, amelyet egy stoppolt fehér golyó egyenesen eltalál. Tökéletesen rugalmas golyókkal (ebben a fájlban a golyó–golyó ütközési szám 1) a lökés végigfut a soron, ugyanabban a pillanatban egyik érintkező párról a másikra, és csak az utolsó golyó indul el, a fehér golyó sebességével. Visszapattan a hátsó mantinelről, visszaér a sorba, és ezúttal a fehér golyót lökik vissza. Állítsa vissza az ütközési számot 0,95-re, és az energia ehelyett szétoszlik a sor mentén.</translation>
    </message>
    <message>
        <source>One-cushion bank</source>
        <translation>Egymantineles bank</translation>
    </message>
    <message>
        <source>Bank the 1 off the top rail into the bottom side pocket. The mirror method aims at the pocket&apos;s image behind the rail: 81.7° from here. A real rail is no mirror: the 1 leaves it with less speed along the normal than it came in with (restitution 0.85), sliding, with the rail&apos;s friction acting on it. In this setup headings from about 80.4° to 82.0° make the bank; 81.2° is the middle of that window, a little below the mirror aim.</source>
        <translation>Lökje az 1-est a felső mantinelről az alsó középső lyukba. A tükörmódszer a lyuknak a mantinel mögötti tükörképére céloz: innen 81,7°. Egy valódi mantinel nem tükör: az 1-es a normális mentén kisebb sebességgel hagyja el, mint amellyel érkezett (ütközési szám 0,85), csúszva, a mantinel súrlódásától érintve. Ebben a felállásban nagyjából 80,4° és 82,0° közötti irányok hozzák a bankot; 81,2° ennek az ablaknak a közepe, kicsivel a tükörirány alatt.</translation>
    </message>
    <message>
        <source>Snooker plant</source>
        <translation>Snooker-kombináció (plant)</translation>
    </message>
    <message>
        <source>Two reds touching, their line of centres pointing at the top-right corner pocket. The cue ball drives the first red at 25° to that line, yet the second red goes straight along the line and into the pocket: between touching balls the impulse can only act along their line of centres (friction between the balls is off here). Aim the pair, not the first ball.</source>
        <translation>Két egymáshoz érő piros, centrálegyenesük a jobb felső sarok lyukára mutat. A fehér golyó ehhez a vonalhoz képest 25°-os szögben löki meg az első pirosat, a második piros mégis egyenesen a vonal mentén indul, és a lyukba esik: egymáshoz érő golyók között a lökés csak a centrálegyenesük mentén hathat (a golyók közötti súrlódás itt ki van kapcsolva). A párra célozzon, ne az első golyóra.</translation>
    </message>
    <message>
        <source>Straight shot</source>
        <translation>Egyenes lökés</translation>
    </message>
    <message>
        <source>Cue ball, object ball and the top-right corner pocket on one line: aim through the centre of the 1 and it goes straight in. Struck at the centre, the cue ball slides, then rolls; a rolling cue ball keeps its forward spin through the collision and follows the 1 at about 2/7 of its speed, here stopping about half a metre short of the pocket. Raise the speed to 1.2 m/s and it follows the 1 into the pocket: a scratch.</source>
        <translation>A fehér golyó, a célgolyó és a jobb felső sarok lyuka egy egyenesen: az 1-es közepén át célozva az egyenesen beesik. Középen megütve a fehér golyó csúszik, majd gördül; a gördülő fehér golyó az ütközésen át is megtartja előre pörgését, és sebessége körülbelül 2/7-ével követi az 1-est, itt mintegy fél méterrel a lyuk előtt megállva. Emelje a sebességet 1,2 m/s-ra, és az 1-est a lyukba követi: a fehér lyukba esik.</translation>
    </message>
    <message>
        <source>Stun cut (the 90° rule)</source>
        <translation>Stopvágás (a 90°-os szabály)</translation>
    </message>
    <message>
        <source>The half-ball cut of half-ball-cut.json with the cue ball closer and struck slightly below centre, so that it arrives sliding without spin. A stunned cue ball leaves at 90° to the object ball&apos;s path: exactly 90° with perfectly elastic balls, 87.5° here with restitution 0.95 (tan θ = 2 tan 30° / (1 - e)). The 1 goes into the top-right corner pocket; the cue ball runs along the tangent line to the bottom rail, just short of the bottom-right pocket.</source>
        <translation>A half-ball-cut.json félgolyós vágása, közelebb álló és kissé a közép alatt megütött fehér golyóval, hogy pörgés nélkül, csúszva érkezzen. A stoppolt fehér golyó a célgolyó pályájára merőlegesen távozik: tökéletesen rugalmas golyókkal pontosan 90°-ban, itt, 0,95-ös ütközési számmal 87,5°-ban (tg θ = 2 tg 30° / (1 - e)). Az 1-es a jobb felső sarok lyukába esik; a fehér golyó az érintő mentén az alsó mantinelig fut, épp a jobb alsó lyuk előtt.</translation>
    </message>
    <message>
        <source>Stun shot</source>
        <translation>Stopütés</translation>
    </message>
    <message>
        <source>A straight shot into the top side pocket, struck a little below centre (height -0.18). The backspin wears off on the way, so the cue ball arrives sliding without spin: it hands its whole speed to the 1 and stops dead (with restitution 0.95 it keeps 2.5 % of its speed and creeps on a few millimetres). Compare the follow and draw shots: same balls, different tip height.</source>
        <translation>Egyenes lökés a felső középső lyukba, kissé a közép alatt megütve (magasság -0,18). A hátrapörgés útközben elfogy, így a fehér golyó pörgés nélkül, csúszva érkezik: teljes sebességét átadja az 1-esnek, és megáll (0,95-ös ütközési számmal sebességének 2,5 %-át megtartja, és néhány millimétert továbbkúszik). Hasonlítsa össze az utánfutó és a húzott ütéssel: ugyanazok a golyók, más dákómagasság.</translation>
    </message>
    <message>
        <source>Three-cushion carom</source>
        <translation>Háromfalas karambol</translation>
    </message>
    <message>
        <source>Carom table, no pockets. To score, the white must hit both other balls and touch at least three cushions before it reaches the second one. Here it hits the red first, then runs along the right rail, the bottom rail and the left rail, and comes up into the yellow. Right-hand side spin (side 0.3) lengthens the angle off each rail; headings from about 23.4° to 23.7° score.</source>
        <translation>Karambolasztal, lyukak nélkül. A pontszerzéshez a fehérnek mindkét másik golyót el kell találnia, és legalább három mantinelt érintenie, mielőtt a másodikat eléri. Itt először a pirosat találja el, aztán végigfut a jobb, az alsó és a bal mantinelen, majd felfelé jövet eltalálja a sárgát. A jobb oldalpörgetés (oldal 0,3) minden mantinelnél nyújtja a visszapattanás szögét; nagyjából 23,4° és 23,7° közötti irányokkal lesz pont.</translation>
    </message>
    <message>
        <source>Two-rail kick</source>
        <translation>Kerülés két mantinelről</translation>
    </message>
    <message>
        <source>The 9 hides the 1 from the cue ball. Kick at it off two rails: the bottom rail, then the left rail, and the cue ball comes back into the 1. Headings from about 221.5° to 223.5° find it; the rails take speed and add spin at every contact, so the path is not the mirror path of a ray of light.</source>
        <translation>A 9-es eltakarja az 1-est a fehér golyó elől. Kerülje meg két mantinelről: előbb az alsó, aztán a bal mantinelről, és a fehér golyó visszatér az 1-esre. Nagyjából 221,5° és 223,5° közötti irányok találják el; a mantinelek minden érintkezéskor sebességet vesznek el és pörgetést adnak, ezért a pálya nem egy fénysugár tükörpályája.</translation>
    </message>
</context>
<context>
    <name>cuelab::explain</name>
    <message>
        <source>%1 was potted, and %2 was on</source>
        <translation>%1 esett lyukba, pedig %2 volt soron</translation>
    </message>
    <message>
        <source>a ball other than the 8</source>
        <translation>egy nem 8-as golyó</translation>
    </message>
    <message>
        <source>a colour</source>
        <translation>egy színes golyó</translation>
    </message>
    <message>
        <source>a red</source>
        <translation>egy piros</translation>
    </message>
    <message>
        <source>a solid</source>
        <translation>egy teli golyó</translation>
    </message>
    <message>
        <source>a stripe</source>
        <translation>egy csíkos golyó</translation>
    </message>
    <message>
        <source>after the first contact no ball was pocketed and none reached a cushion</source>
        <translation>az első érintkezés után egy golyó sem esett lyukba, és egy sem ért mantinelt</translation>
    </message>
    <message>
        <source>ball %1 left the table</source>
        <translation>a(z) %1 golyó elhagyta az asztalt</translation>
    </message>
    <message>
        <source>foul (%1): %2; %3 points to the opponent</source>
        <translation>szabálytalanság (%1): %2; %3 pont az ellenfélnek</translation>
    </message>
    <message>
        <source>foul (%1): %2; ball in hand for the opponent</source>
        <translation>szabálytalanság (%1): %2; az ellenfél kézből helyezi a fehér golyót</translation>
    </message>
    <message>
        <source>foul (%1): %2; no point, the turn passes</source>
        <translation>szabálytalanság (%1): %2; nincs pont, a másik játékos következik</translation>
    </message>
    <message>
        <source>foul (%1): %2; the striker loses the rack</source>
        <translation>szabálytalanság (%1): %2; a játékos elveszíti a játszmát</translation>
    </message>
    <message>
        <source>legal, but no ball fell into the called %1; the turn passes</source>
        <translation>szabályos, de a bemondott lyukba (%1) nem esett golyó; a másik játékos következik</translation>
    </message>
    <message>
        <source>legal: %1 pocketed; the striker plays on</source>
        <translation>szabályos: lyukba esett: %1; a játékos folytatja</translation>
    </message>
    <message>
        <source>legal: %1 pocketed; the striker wins the rack</source>
        <translation>szabályos: lyukba esett: %1; a játékos megnyeri a játszmát</translation>
    </message>
    <message>
        <source>legal: %1 potted (+%2); the striker plays on</source>
        <translation>szabályos: lyukba esett: %1 (+%2); a játékos folytatja</translation>
    </message>
    <message>
        <source>legal: nothing pocketed; the turn passes</source>
        <translation>szabályos: nem esett golyó lyukba; a másik játékos következik</translation>
    </message>
    <message>
        <source>legal: nothing potted; the turn passes</source>
        <translation>szabályos: nem esett golyó lyukba; az ellenfél következik</translation>
    </message>
    <message>
        <source>no point: the cue ball met %1 after only %2 cushions (three needed)</source>
        <translation>nincs pont: a fehér golyó csak %2 mantinel után érte el ezt: %1 (három kell)</translation>
    </message>
    <message>
        <source>no point: the cue ball met %1 only</source>
        <translation>nincs pont: a fehér golyó csak ezt érte el: %1</translation>
    </message>
    <message>
        <source>no point: the cue ball met no object ball</source>
        <translation>nincs pont: a fehér golyó egyik tárgygolyót sem érte el</translation>
    </message>
    <message>
        <source>point: the cue ball met %1, then %2 after %3 cushions</source>
        <translation>pont: a fehér golyó előbb ezt érte el: %1, majd %3 mantinel után ezt: %2</translation>
    </message>
    <message>
        <source>the 8 fell into %1, not into the called %2</source>
        <translation>a 8-as ide esett: %1, nem a bemondott lyukba (%2)</translation>
    </message>
    <message>
        <source>the 8 went down before the striker&apos;s group was cleared</source>
        <translation>a 8-as lyukba esett, mielőtt a játékos a saját csoportját letisztította volna</translation>
    </message>
    <message>
        <source>the break pocketed no ball and drove %1 object balls to a cushion, not four</source>
        <translation>a kezdőlökés nem juttatott golyót lyukba, és csak %1 tárgygolyót vitt mantinelhez négy helyett</translation>
    </message>
    <message>
        <source>the cue ball fell into %1</source>
        <translation>a fehér golyó lyukba esett: %1</translation>
    </message>
    <message>
        <source>the cue ball first touched %1, not %2</source>
        <translation>a fehér golyó először ezt érintette: %1, nem ezt: %2</translation>
    </message>
    <message>
        <source>the cue ball touched no ball</source>
        <translation>a fehér golyó egy golyót sem érintett</translation>
    </message>
    <message>
        <source>Motion after</source>
        <translation>Mozgás utána</translation>
    </message>
    <message>
        <source>u′ = v′ + R (z × ω′)   (the slip at the cloth decides the state)</source>
        <translation>u′ = v′ + R (z × ω′)   (a posztón mért csúszás dönti el az állapotot)</translation>
    </message>
    <message>
        <source>%1 leaves %2</source>
        <translation>%1 ezután: %2</translation>
    </message>
    <message>
        <source>A ball whose cloth contact slips slides; one whose contact does not slip rolls. %1.</source>
        <translation>Az a golyó, amelynek posztón fekvő érintkezési pontja csúszik, csúszik; amelyiké nem csúszik, az gördül. %1.</translation>
    </message>
    <message>
        <source>The held group</source>
        <translation>A tartósan érintkező csoport</translation>
    </message>
    <message>
        <source>The pair joins the balls it is already held with: their contacts are solved together, and what relative normal speed the others have left is taken away at the same time (each ball answers with 1/m sliding, 5/7 1/m rolling). These are the states the simulation goes on from.</source>
        <translation>A pár csatlakozik azokhoz a golyókhoz, amelyekkel már tartósan érintkezik: érintkezéseiket együtt oldjuk meg, és a többiek megmaradt relatív normális sebességét ugyanabban a lépésben elvesszük (minden golyó csúszva 1/m, gördülve 5/7 · 1/m arányban válaszol). Ezekből az állapotokból folytatódik a szimuláció.</translation>
    </message>
    <message>
        <source>v″ (after the group&apos;s contacts are seated)</source>
        <translation>v″ (a csoport érintkezéseinek rendezése után)</translation>
    </message>
    <message>
        <source>Ball-ball collision of %1 and %2</source>
        <translation>Golyó–golyó ütközés: %1 és %2</translation>
    </message>
    <message>
        <source>%1 (μ: Alciatore&apos;s fit)</source>
        <translation>%1 (μ: Alciatore illesztése)</translation>
    </message>
    <message>
        <source>%1 (μ fixed)</source>
        <translation>%1 (rögzített μ)</translation>
    </message>
    <message>
        <source>The balls touch when their centres are R_a + R_b apart (a = %1, b = %2). Both move on quadratic paths since t_0, so the squared distance is a quartic in τ.</source>
        <translation>A golyók akkor érnek össze, amikor középpontjuk távolsága R_a + R_b (a = %1, b = %2). t_0 óta mindkettő másodfokú pályán mozog, ezért a távolság négyzete τ negyedfokú polinomja.</translation>
    </message>
    <message>
        <source>The balls rest on the cloth with their centres at the heights R_a and R_b, so they touch when their centres are d = √((R_a + R_b)^2 − (R_a − R_b)^2) = 2 √(R_a R_b) apart horizontally (a = %1, b = %2). Both move on quadratic paths since t_0, so the squared distance is a quartic in τ.</source>
        <translation>A golyók a posztón fekszenek, középpontjuk R_a, illetve R_b magasságban van, ezért akkor érnek össze, amikor középpontjaik vízszintes távolsága d = √((R_a + R_b)^2 − (R_a − R_b)^2) = 2 √(R_a R_b) (a = %1, b = %2). t_0 óta mindkettő másodfokú pályán mozog, ezért a távolság négyzete τ negyedfokú polinomja.</translation>
    </message>
    <message>
        <source>Contact geometry</source>
        <translation>Az érintkezés geometriája</translation>
    </message>
    <message>
        <source>The normal n points from the centre of a to the centre of b; the contact point lies R_a along it. The balls approach when their relative velocity along n is positive.</source>
        <translation>Az n normális a középpontjától b középpontja felé mutat; az érintkezési pont ezen R_a távolságra van. A golyók akkor közelednek, ha relatív sebességük n irányú összetevője pozitív.</translation>
    </message>
    <message>
        <source>Contact geometry (unequal radii)</source>
        <translation>Az érintkezés geometriája (különböző sugarak)</translation>
    </message>
    <message>
        <source>The centres sit at the heights R_a and R_b, so the contact normal n₃ from the centre of a to the centre of b leaves the cloth plane: its level part is c û, with û the horizontal direction from a to b. The contact point lies R_a along n₃ (r_c is its place on the cloth plane). The balls approach when their relative velocity along n₃ is positive; it has no vertical part, since both balls stay on the cloth.</source>
        <translation>A középpontok R_a, illetve R_b magasságban vannak, ezért az a középpontjától b középpontja felé mutató n₃ érintkezési normális kilép a posztó síkjából: vízszintes része c û, ahol û az a-tól b felé mutató vízszintes irány. Az érintkezési pont n₃ mentén R_a távolságra van (r_c ennek helye a posztó síkjában). A golyók akkor közelednek, ha relatív sebességük n₃ irányú összetevője pozitív; ennek nincs függőleges része, mert mindkét golyó a posztón marad.</translation>
    </message>
    <message>
        <source>Collision law (%1)</source>
        <translation>Ütközési törvény (%1)</translation>
    </message>
    <message>
        <source>No step-by-step explanation of this model yet.</source>
        <translation>Ehhez a modellhez még nincs lépésenkénti magyarázat.</translation>
    </message>
    <message>
        <source>Held in contact (a push)</source>
        <translation>Tartós érintkezés (tolás)</translation>
    </message>
    <message>
        <source>The collision turns some energy into sound and heat (restitution e &lt; 1, friction).</source>
        <translation>Az ütközés az energia egy részét hanggá és hővé alakítja (ütközési szám e &lt; 1, súrlódás).</translation>
    </message>
    <message>
        <source>The impulses on the two balls are equal and opposite, so their horizontal momentum is kept (up to the vertical part of a frictional impulse, taken up by the cloth).</source>
        <translation>A két golyóra ható erőlökés egyenlő nagyságú és ellentétes irányú, ezért vízszintes lendületük összege megmarad (egy súrlódásos erőlökés függőleges részéig, amelyet a posztó vesz fel).</translation>
    </message>
    <message>
        <source>Ball-jaw collision of %1 with %2</source>
        <translation>Golyó–pofa ütközés: %1 golyó – %2</translation>
    </message>
    <message>
        <source>Ball-cushion collision of %1 with %2</source>
        <translation>Golyó–mantinel ütközés: %1 golyó – %2</translation>
    </message>
    <message>
        <source>The ball touches the jaw&apos;s rounded tip (a circle of radius r_{jaw} around c) when its centre is R + r_{jaw} from c: a quartic in τ.</source>
        <translation>A golyó akkor éri el a pofa lekerekített végét (egy r_{jaw} sugarú kört c körül), amikor középpontja R + r_{jaw} távolságra van c-től: ez τ negyedfokú polinomja.</translation>
    </message>
    <message>
        <source>The ball touches the straight cushion nose when its centre is R from the nose line (normal N into the table): a quadratic in τ, whose contact point must also lie on the segment.</source>
        <translation>A golyó akkor éri el az egyenes mantinel élét, amikor középpontja R távolságra van az él egyenesétől (N normális az asztal belseje felé): ez τ másodfokú polinomja, és az érintkezési pontnak a szakaszon is rajta kell lennie.</translation>
    </message>
    <message>
        <source>Segment check</source>
        <translation>Szakaszpróba</translation>
    </message>
    <message>
        <source>The foot of the perpendicular from the centre to the nose line must lie between the segment&apos;s ends p_a and p_b (0 ≤ λ ≤ 1); otherwise the ball passes the end of this cushion (into a pocket mouth, or onto a jaw).</source>
        <translation>A középpontból az él egyenesére bocsátott merőleges talppontjának a szakasz p_a és p_b végpontja között kell lennie (0 ≤ λ ≤ 1); különben a golyó elhalad ennek a mantinelnek a vége mellett (egy lyuk szájába vagy egy pofára).</translation>
    </message>
    <message>
        <source>on segment</source>
        <translation>a szakaszon</translation>
    </message>
    <message>
        <source>The normal N points from the jaw tip&apos;s centre c to the ball&apos;s centre; the contact lies R behind the centre along −N.</source>
        <translation>Az N normális a pofavég c középpontjától a golyó középpontja felé mutat; az érintkezés a középpont mögött R távolságra van, −N irányban.</translation>
    </message>
    <message>
        <source>The normal N of the cushion points into the table; the contact lies R behind the centre along −N. The ball approaches when v·N &lt; 0.</source>
        <translation>A mantinel N normálisa az asztal belseje felé mutat; az érintkezés a középpont mögött R távolságra van, −N irányban. A golyó akkor közeledik, ha v·N &lt; 0.</translation>
    </message>
    <message>
        <source>N = (r − c)/|r − c|  (jaw),   r_c = r − R N,   v_n = −v·N</source>
        <translation>N = (r − c)/|r − c|  (pofa),   r_c = r − R N,   v_n = −v·N</translation>
    </message>
    <message>
        <source>The cushion absorbs part of the energy (restitution e &lt; 1, friction at the contact).</source>
        <translation>A mantinel az energia egy részét elnyeli (ütközési szám e &lt; 1, súrlódás az érintkezésnél).</translation>
    </message>
    <message>
        <source>The cushion pushes the ball: the change of its momentum is the cushion&apos;s horizontal impulse J.</source>
        <translation>A mantinel meglöki a golyót: lendületének megváltozása a mantinel vízszintes J erőlökése.</translation>
    </message>
    <message>
        <source>Cue strike on %1</source>
        <translation>Dákóütés: %1 golyó</translation>
    </message>
    <message>
        <source>Cue strike</source>
        <translation>Dákóütés</translation>
    </message>
    <message>
        <source>The setup&apos;s shot is not known here; the event holds its result.</source>
        <translation>A beállítás ütése itt nem ismert; az esemény az eredményét tartalmazza.</translation>
    </message>
    <message>
        <source>Where the tip meets the ball</source>
        <translation>Ahol a dákóvég a golyót éri</translation>
    </message>
    <message>
        <source>The tip offsets are fractions of R: a to the player&apos;s right, b above the centre; the contact lies c behind the centre along the cue&apos;s heading d. The offsets lay beyond the ball&apos;s silhouette and were scaled onto it.</source>
        <translation>A dákóvég eltolásai R törtrészei: a a játékos jobb keze felé, b a középpont fölé; az érintkezés a középpont mögött c távolságra van, a dákó d iránya mentén. Az eltolások a golyó körvonalán kívül estek, ezért a körvonalra lettek lekicsinyítve.</translation>
    </message>
    <message>
        <source>The tip offsets are fractions of R: a to the player&apos;s right, b above the centre; the contact lies c behind the centre along the cue&apos;s heading d.</source>
        <translation>A dákóvég eltolásai R törtrészei: a a játékos jobb keze felé, b a középpont fölé; az érintkezés a középpont mögött c távolságra van, a dákó d iránya mentén.</translation>
    </message>
    <message>
        <source>Impulse of the tip (Alciatore TP A-30)</source>
        <translation>A dákóvég erőlökése (Alciatore, TP A-30)</translation>
    </message>
    <message>
        <source>The cue (mass M at speed V_0) hits the ball elastically at Q along e. Momentum and energy of cue and ball, with the ball&apos;s rotation about its centre (I = 2/5 m R²), give the impulse F. For a level cue this is v = 2 V_0 / (1 + m/M + 5 (a² + b²)/(2 R²)).</source>
        <translation>A dákó (tömege M, sebessége V_0) rugalmasan üti meg a golyót Q-ban, e mentén. A dákó és a golyó lendülete és energiája – a golyó középpontja körüli forgásával együtt (I = 2/5 m R²) – adja az F erőlökést. Vízszintes dákóval ez v = 2 V_0 / (1 + m/M + 5 (a² + b²)/(2 R²)).</translation>
    </message>
    <message>
        <source>Velocity and spin after the strike</source>
        <translation>Sebesség és pörgés az ütés után</translation>
    </message>
    <message>
        <source>The impulse F e moves the centre (its vertical part is taken up by the cloth) and its torque Q × F e about the centre spins the ball: top spin for b &gt; 0, right english (ω_z &gt; 0) for a &gt; 0. The ball leaves %1.</source>
        <translation>Az F e erőlökés elmozdítja a középpontot (függőleges részét a posztó veszi fel), a középpontra vett Q × F e forgatónyomatéka pedig megpörgeti a golyót: b &gt; 0 esetén felső pörgés, a &gt; 0 esetén jobb oldalpörgés (ω_z &gt; 0). A golyó ezután %1.</translation>
    </message>
    <message>
        <source>The cue brings ½ M V_0² = %1 J; an elastic tip keeps the total, so the cue keeps the rest.</source>
        <translation>A dákó ½ M V_0² = %1 J energiát hoz; a rugalmas dákóvég megtartja az összeget, így a maradék a dákónál marad.</translation>
    </message>
    <message>
        <source>The ball&apos;s momentum is the horizontal part of the impulse F e.</source>
        <translation>A golyó lendülete az F e erőlökés vízszintes része.</translation>
    </message>
    <message>
        <source>Since t_{start} %1 has been %2: in closed form its centre moves on a parabola with constant acceleration q − μ_s g û: it is held in a push, and the contact force N/m = q adds to the friction −μ_s g û against the slip û of its cloth contact.</source>
        <translation>t_{start} óta a(z) %1 golyó %2: zárt alakban a középpontja parabolán mozog, állandó q − μ_s g û gyorsulással: tartós érintkezésben (tolásban) van, és az N/m = q érintkezési erő hozzáadódik a posztón fekvő érintkezési pont û csúszása ellen ható −μ_s g û súrlódáshoz.</translation>
    </message>
    <message>
        <source>Since t_{start} %1 has been %2: in closed form its centre moves on a parabola with constant acceleration −μ_s g û against the slip û of its cloth contact.</source>
        <translation>t_{start} óta a(z) %1 golyó %2: zárt alakban a középpontja parabolán mozog, állandó −μ_s g û gyorsulással, a posztón fekvő érintkezési pont û csúszása ellen.</translation>
    </message>
    <message>
        <source>Since t_{start} %1 has been %2: in closed form its centre moves on a parabola with constant acceleration (5/7) q − μ_r g v̂: it is held in a push, and static friction keeps it rolling under the contact force N/m = q (its effective mass is 7/5 m).</source>
        <translation>t_{start} óta a(z) %1 golyó %2: zárt alakban a középpontja parabolán mozog, állandó (5/7) q − μ_r g v̂ gyorsulással: tartós érintkezésben (tolásban) van, és a tapadási súrlódás gördülésben tartja az N/m = q érintkezési erő alatt (effektív tömege 7/5 m).</translation>
    </message>
    <message>
        <source>Since t_{start} %1 has been %2: in closed form its centre moves on a parabola with constant acceleration −μ_r g v̂ (rolling resistance).</source>
        <translation>t_{start} óta a(z) %1 golyó %2: zárt alakban a középpontja parabolán mozog, állandó −μ_r g v̂ gyorsulással (gördülési ellenállás).</translation>
    </message>
    <message>
        <source>Motion of %1 up to the event</source>
        <translation>A(z) %1 golyó mozgása az eseményig</translation>
    </message>
    <message>
        <source>Kinetic energy before and after</source>
        <translation>Mozgási energia előtte és utána</translation>
    </message>
    <message>
        <source>Translation ½ m |v|² plus rotation ½ I |ω|² (I = 2/5 m R²) of each ball.</source>
        <translation>Minden golyóra a haladás ½ m |v|² energiája és a forgás ½ I |ω|² energiája (I = 2/5 m R²).</translation>
    </message>
    <message>
        <source>Momentum before and after</source>
        <translation>Lendület előtte és utána</translation>
    </message>
    <message>
        <source>Inputs:</source>
        <translation>Bemenetek:</translation>
    </message>
    <message>
        <source>Results:</source>
        <translation>Eredmények:</translation>
    </message>
    <message>
        <source>%1 (event %2, t = %3 s)</source>
        <translation>%1 (esemény: %2, t = %3 s)</translation>
    </message>
    <message>
        <source>Collision model: %1</source>
        <translation>Ütközési modell: %1</translation>
    </message>
    <message>
        <source>Roots of f(τ):</source>
        <translation>f(τ) gyökei:</translation>
    </message>
    <message>
        <source>chosen</source>
        <translation>ez a választott</translation>
    </message>
    <message>
        <source>outside the window</source>
        <translation>az ablakon kívül</translation>
    </message>
    <message>
        <source>the bodies part</source>
        <translation>a testek távolodnak</translation>
    </message>
    <message>
        <source>off the segment</source>
        <translation>a szakaszon kívül</translation>
    </message>
    <message>
        <source>later</source>
        <translation>későbbi</translation>
    </message>
    <message>
        <source>none</source>
        <translation>nincs</translation>
    </message>
    <message>
        <source>Ball %1 drops into %2</source>
        <translation>Lyukba esés: %1 golyó – %2</translation>
    </message>
    <message>
        <source>Off the table</source>
        <translation>Le az asztalról</translation>
    </message>
    <message>
        <source>The ball leaves the table; it is kept at the pocket&apos;s centre with no motion and no energy.</source>
        <translation>A golyó elhagyja az asztalt; a lyuk középpontjában marad, mozgás és energia nélkül.</translation>
    </message>
    <message>
        <source>The pocket takes all of the ball&apos;s kinetic energy.</source>
        <translation>A lyuk elnyeli a golyó teljes mozgási energiáját.</translation>
    </message>
    <message>
        <source>f(τ) = (r(t_0+τ) − p_a)·N − R   (signed distance of the centre from the cushion line, minus R)</source>
        <translation>f(τ) = (r(t_0+τ) − p_a)·N − R   (a középpont előjeles távolsága a mantinel egyenesétől, mínusz R)</translation>
    </message>
    <message>
        <source>The centre was already over the pocket at t_0: the ball drops at once (τ = 0).</source>
        <translation>A középpont t_0-kor már a lyuk fölött volt: a golyó azonnal beesik (τ = 0).</translation>
    </message>
    <message>
        <source>The bodies were touching at t_0 (within 10^{−10} m) and approaching, or pressed together at rest: the contact begins at once (τ = 0).</source>
        <translation>A testek t_0-kor már érintkeztek (10^{−10} m-en belül) és közeledtek, vagy nyugalomban egymásnak nyomódtak: az érintkezés azonnal kezdődik (τ = 0).</translation>
    </message>
    <message>
        <source>τ* is the smallest root in the prediction window 0 &lt; τ ≤ H at which f falls (f′(τ) &lt; 0: the bodies approach); a root where f rises (they part) or only touches zero (a graze) is passed over, and the contact point must lie between the segment&apos;s ends.</source>
        <translation>τ* a 0 &lt; τ ≤ H előrejelzési ablak legkisebb olyan gyöke, ahol f csökken (f′(τ) &lt; 0: a testek közelednek); azt a gyököt, ahol f nő (a testek távolodnak), vagy ahol csak érinti a nullát (súrolás), átugorjuk, és az érintkezési pontnak a szakasz végpontjai között kell lennie.</translation>
    </message>
    <message>
        <source>τ* is the smallest root in the prediction window 0 &lt; τ ≤ H at which f falls (f′(τ) &lt; 0: the bodies approach); a root where f rises (they part) or only touches zero (a graze) is passed over.</source>
        <translation>τ* a 0 &lt; τ ≤ H előrejelzési ablak legkisebb olyan gyöke, ahol f csökken (f′(τ) &lt; 0: a testek közelednek); azt a gyököt, ahol f nő (a testek távolodnak), vagy ahol csak érinti a nullát (súrolás), átugorjuk.</translation>
    </message>
    <message>
        <source>Why now: the time of impact</source>
        <translation>Miért éppen most: az ütközés időpontja</translation>
    </message>
    <message>
        <source>Transition %1 of %2</source>
        <translation>Mozgásváltás (%1): %2 golyó</translation>
    </message>
    <message>
        <source>Why now: the pushed slide ends</source>
        <translation>Miért éppen most: véget ér a tolt csúszás</translation>
    </message>
    <message>
        <source>The ball is held in a push: besides the cloth&apos;s friction −μ_s g û a contact force q = N/m acts through its centre, so its slip changes at q − (7/2) μ_s g û and its component along û reaches zero after t_s.</source>
        <translation>A golyó tartós érintkezésben (tolásban) van: a posztó −μ_s g û súrlódása mellett egy q = N/m érintkezési erő is hat a középpontján át, így csúszása q − (7/2) μ_s g û ütemben változik, û irányú összetevője pedig t_s idő alatt nullára csökken.</translation>
    </message>
    <message>
        <source>Why now: the pushed ball stops rolling</source>
        <translation>Miért éppen most: a tolt golyó gördülése megáll</translation>
    </message>
    <message>
        <source>The ball is held in a push and rolls under the contact force q = N/m with the effective mass 7/5 m: its speed changes at (5/7) q·v̂ − μ_r g and reaches zero after t_r.</source>
        <translation>A golyó tartós érintkezésben (tolásban) van, és a q = N/m érintkezési erő alatt 7/5 m effektív tömeggel gördül: sebessége (5/7) q·v̂ − μ_r g ütemben változik, és t_r idő alatt nullára csökken.</translation>
    </message>
    <message>
        <source>Why now: the end of the slide</source>
        <translation>Miért éppen most: véget ér a csúszás</translation>
    </message>
    <message>
        <source>Cloth friction −μ_s m g û slows the slip u = v + R (z × ω) of the contact point: it changes v by −μ_s g û and R (z × ω) by −(5/2) μ_s g û, so u falls at (7/2) μ_s g along a fixed direction and reaches zero after t_s.</source>
        <translation>A posztó −μ_s m g û súrlódása lassítja az érintkezési pont u = v + R (z × ω) csúszását: v-t −μ_s g û, R (z × ω)-t −(5/2) μ_s g û ütemben változtatja, így u állandó irányban (7/2) μ_s g ütemben csökken, és t_s idő alatt nullára ér.</translation>
    </message>
    <message>
        <source>Natural roll</source>
        <translation>Természetes gördülés</translation>
    </message>
    <message>
        <source>The slide ends at rest</source>
        <translation>A csúszás nyugalomban ér véget</translation>
    </message>
    <message>
        <source>When the slip stops the ball rolls at v = (5/7) v_0 + (2/7) R (ω_0 × z), whatever μ_s is.</source>
        <translation>Amikor a csúszás megszűnik, a golyó v = (5/7) v_0 + (2/7) R (ω_0 × z) sebességgel gördül, bármekkora is μ_s.</translation>
    </message>
    <message>
        <source>The slide ends with the velocity at zero (draw or stun used the speed up exactly); what spin about z is left keeps decaying.</source>
        <translation>A csúszás nulla sebességgel ér véget (a húzás vagy a stop pontosan felemésztette a sebességet); a megmaradt z körüli pörgés tovább csillapodik.</translation>
    </message>
    <message>
        <source>Why now: the ball stops rolling</source>
        <translation>Miért éppen most: a golyó gördülése megáll</translation>
    </message>
    <message>
        <source>Rolling resistance slows a rolling ball at μ_r g; it stops after t_r (having covered |v_0|²/(2 μ_r g)).</source>
        <translation>A gördülési ellenállás μ_r g ütemben lassítja a gördülő golyót; t_r idő alatt áll meg (addig |v_0|²/(2 μ_r g) utat tesz meg).</translation>
    </message>
    <message>
        <source>Why now: the spin about z dies</source>
        <translation>Miért éppen most: elhal a z körüli pörgés</translation>
    </message>
    <message>
        <source>Spin friction decelerates the spin about the vertical at α = 5 μ_{sp} g / (2R) in every state; a spinning ball stops when ω_z reaches zero.</source>
        <translation>A pörgési súrlódás minden állapotban α = 5 μ_{sp} g / (2R) szöggyorsulással lassítja a függőleges tengely körüli pörgést; a helyben pörgő golyó megáll, amikor ω_z nullára ér.</translation>
    </message>
    <message>
        <source>State at the transition</source>
        <translation>Állapot a mozgásváltáskor</translation>
    </message>
    <message>
        <source>The closed-form motion evolved to the transition, its numbers made exact (a rolling ball&apos;s spin follows its velocity; a stopped ball has v = 0). The ball is now %1.</source>
        <translation>A zárt alakú mozgás a mozgásváltásig léptetve, számai pontosra igazítva (a gördülő golyó pörgése követi a sebességét; a megállt golyóra v = 0). A golyó most %1.</translation>
    </message>
    <message>
        <source>r(t), v(t), ω(t) from the segment&apos;s closed form</source>
        <translation>r(t), v(t), ω(t) a szakasz zárt alakjából</translation>
    </message>
    <message>
        <source>The held group is solved again</source>
        <translation>A tartósan érintkező csoportot újra megoldjuk</translation>
    </message>
    <message>
        <source>A ball of a held push changed its motion, so the contact forces of its group are solved again (and what relative normal speed the contacts have left is taken away).</source>
        <translation>Egy tartósan érintkező golyó mozgása megváltozott, ezért csoportja érintkezési erőit újra megoldjuk (és az érintkezések megmaradt relatív normális sebességét elvesszük).</translation>
    </message>
    <message>
        <source>v″, ω″ after the group&apos;s contacts are seated</source>
        <translation>v″, ω″ a csoport érintkezéseinek rendezése után</translation>
    </message>
    <message>
        <source>Energy is continuous at a transition; since t_{start} friction has taken %1 J.</source>
        <translation>Mozgásváltáskor az energia folytonos; t_{start} óta a súrlódás %1 J energiát vont el.</translation>
    </message>
    <message>
        <source>Normal impulse (with restitution)</source>
        <translation>Normális irányú erőlökés (ütközési számmal)</translation>
    </message>
    <message>
        <source>Along the line of centres the balls part at e times their approach speed.</source>
        <translation>A centrálegyenes mentén a golyók a közeledési sebességük e-szeresével távolodnak.</translation>
    </message>
    <message>
        <source>Normal impulse (with restitution, balls held on the cloth)</source>
        <translation>Normális irányú erőlökés (ütközési számmal, a posztón tartott golyókkal)</translation>
    </message>
    <message>
        <source>Along the tilted normal n₃ the balls part at e times their approach speed. Both stay on the cloth, which takes the vertical part of the impulse, so P_n lowers the approach speed by c^2 (1/m_a + 1/m_b) P_n.</source>
        <translation>A ferde n₃ normális mentén a golyók a közeledési sebességük e-szeresével távolodnak. Mindkettő a posztón marad, amely felveszi az erőlökés függőleges részét, így P_n a közeledési sebességet c^2 (1/m_a + 1/m_b) P_n-nel csökkenti.</translation>
    </message>
    <message>
        <source>Slip of the contact points</source>
        <translation>Az érintkezési pontok csúszása</translation>
    </message>
    <message>
        <source>The surfaces at the contact move at v + ω × (±R n); their relative velocity across n is the slip that friction between the balls opposes (it throws the object ball off the line of centres).</source>
        <translation>Az érintkezésnél a felületek v + ω × (±R n) sebességgel mozognak; n-re merőleges relatív sebességük az a csúszás, amely ellen a golyók közti súrlódás hat (ez téríti el a célgolyót a centrálegyenestől).</translation>
    </message>
    <message>
        <source>The surfaces at the contact move at v + ω × (±R n₃); their relative velocity across n₃ is the slip that friction between the balls opposes. With the tilted normal the normal impulse itself changes that slip, so it is taken with the velocities v after the normal impulse (v = v_a − (P_n/m_a) c û, v_b + (P_n/m_b) c û).</source>
        <translation>Az érintkezésnél a felületek v + ω × (±R n₃) sebességgel mozognak; n₃-ra merőleges relatív sebességük az a csúszás, amely ellen a golyók közti súrlódás hat. Ferde normálisnál maga a normális irányú erőlökés is megváltoztatja ezt a csúszást, ezért a normális erőlökés utáni v sebességekkel számolunk (v = v_a − (P_n/m_a) c û, v_b + (P_n/m_b) c û).</translation>
    </message>
    <message>
        <source>s = (v_a + ω_a × R_a n) − (v_b − ω_b × R_b n),   tangential part</source>
        <translation>s = (v_a + ω_a × R_a n) − (v_b − ω_b × R_b n),   érintőleges rész</translation>
    </message>
    <message>
        <source>s = (v + ω_a × R_a n₃)_a − (v − ω_b × R_b n₃)_b,   tangential part (across n₃)</source>
        <translation>s = (v + ω_a × R_a n₃)_a − (v − ω_b × R_b n₃)_b,   érintőleges rész (n₃-ra merőlegesen)</translation>
    </message>
    <message>
        <source>Friction coefficient (Alciatore&apos;s fit, TP A-14)</source>
        <translation>Súrlódási együttható (Alciatore illesztése, TP A-14)</translation>
    </message>
    <message>
        <source>Ball-ball friction falls with the sliding speed at the contact.</source>
        <translation>A golyók közti súrlódás az érintkezésnél mért csúszási sebességgel csökken.</translation>
    </message>
    <message>
        <source>Friction coefficient (fixed)</source>
        <translation>Súrlódási együttható (rögzített)</translation>
    </message>
    <message>
        <source>The setup gives a fixed ball-ball friction.</source>
        <translation>A beállítás rögzített golyó–golyó súrlódást ad meg.</translation>
    </message>
    <message>
        <source>Coulomb limit reached: the balls keep slipping</source>
        <translation>Elérte a Coulomb-határt: a golyók tovább csúsznak</translation>
    </message>
    <message>
        <source>Slip stopped: below the Coulomb limit</source>
        <translation>A csúszás megállt: a Coulomb-határ alatt</translation>
    </message>
    <message>
        <source>Friction gives at most μ_b P_n (Coulomb), and never more than the impulse that stops the slip, |s| / (7/2 (1/m_a + 1/m_b)) for solid spheres (effective mass m/7 for equal balls). The smaller of the two acts, against the slip.</source>
        <translation>A súrlódás legfeljebb μ_b P_n erőlökést ad (Coulomb), és sosem többet annál, amely megállítja a csúszást: tömör gömbökre |s| / (7/2 (1/m_a + 1/m_b)) (egyenlő golyókra m/7 effektív tömeg). A kettő közül a kisebbik hat, a csúszással szemben.</translation>
    </message>
    <message>
        <source>limited</source>
        <translation>korlátozott</translation>
    </message>
    <message>
        <source>Velocities and spins after</source>
        <translation>Sebességek és pörgések utána</translation>
    </message>
    <message>
        <source>Both impulses change the velocities; the tangential one also turns the spins by its torque (R n) × J_t over I = 2/5 m R² (its vertical part is taken up by the cloth).</source>
        <translation>Mindkét erőlökés megváltoztatja a sebességeket; az érintőleges a forgatónyomatékával, (R n) × J_t osztva I = 2/5 m R²-tel, a pörgéseket is elfordítja (függőleges részét a posztó veszi fel).</translation>
    </message>
    <message>
        <source>Normal impulse (frictionless, with restitution)</source>
        <translation>Normális irányú erőlökés (súrlódásmentes, ütközési számmal)</translation>
    </message>
    <message>
        <source>The balls push on each other only along the line of centres n. Newton&apos;s restitution law makes them part at e times the speed at which they approached; with momentum kept this fixes the impulse. For equal masses it is Δ = (1+e)/2 (v_{rel}·n) n on each velocity.</source>
        <translation>A golyók csak az n centrálegyenes mentén nyomják egymást. Newton ütközési törvénye szerint a közeledési sebességük e-szeresével válnak szét; a lendület megmaradásával ez meghatározza az erőlökést. Egyenlő tömegekre ez minden sebességen Δ = (1+e)/2 (v_{rel}·n) n.</translation>
    </message>
    <message>
        <source>Velocities after</source>
        <translation>Sebességek utána</translation>
    </message>
    <message>
        <source>The impulse −P_n n acts on %1 (a) and +P_n n on %2 (b); without friction there is no torque about the centres, so the spins stay as they were.</source>
        <translation>A −P_n n erőlökés a(z) %1 golyóra (a), a +P_n n a(z) %2 golyóra (b) hat; súrlódás nélkül nincs forgatónyomaték a középpontokra, így a pörgések nem változnak.</translation>
    </message>
    <message>
        <source>Normal impulse (frictionless, with restitution, balls held on the cloth)</source>
        <translation>Normális irányú erőlökés (súrlódásmentes, ütközési számmal, a posztón tartott golyókkal)</translation>
    </message>
    <message>
        <source>The balls push on each other only along the tilted normal n₃. They stay on the cloth, which takes the vertical part of the impulse, so an impulse P_n moves only the horizontal velocities, by P_n c û / m, and lowers the approach speed along n₃ by c^2 (1/m_a + 1/m_b) P_n. Newton&apos;s restitution law (they part along n₃ at e times the approach speed) fixes P_n; its horizontal part P_n c is the impulse of a level collision along û.</source>
        <translation>A golyók csak a ferde n₃ normális mentén nyomják egymást. A posztón maradnak, amely felveszi az erőlökés függőleges részét, így egy P_n erőlökés csak a vízszintes sebességeket változtatja, P_n c û / m-mel, és az n₃ menti közeledési sebességet c^2 (1/m_a + 1/m_b) P_n-nel csökkenti. Newton ütközési törvénye (n₃ mentén a közeledési sebesség e-szeresével válnak szét) meghatározza P_n-t; vízszintes része, P_n c, egy û menti vízszintes ütközés erőlökése.</translation>
    </message>
    <message>
        <source>The impulse −P_n n₃ acts on %1 (a) and +P_n n₃ on %2 (b); the cloth takes their vertical parts. Without friction there is no torque about the centres (n₃ passes through both), so the spins stay as they were.</source>
        <translation>A −P_n n₃ erőlökés a(z) %1 golyóra (a), a +P_n n₃ a(z) %2 golyóra (b) hat; függőleges részüket a posztó veszi fel. Súrlódás nélkül nincs forgatónyomaték a középpontokra (n₃ mindkettőn átmegy), így a pörgések nem változnak.</translation>
    </message>
    <message>
        <source>Contact above the equator</source>
        <translation>Érintkezés az egyenlítő fölött</translation>
    </message>
    <message>
        <source>The cushion&apos;s nose is higher than the ball&apos;s centre, so it touches the ball at θ_a above the equator and pushes it down into the cloth as well as back.</source>
        <translation>A mantinel éle magasabban van a golyó középpontjánál, ezért θ_a szöggel az egyenlítő fölött éri a golyót, és nemcsak visszalöki, hanem a posztóba is nyomja.</translation>
    </message>
    <message>
        <source>Rail frame</source>
        <translation>A mantinel koordináta-rendszere</translation>
    </message>
    <message>
        <source>x points into the rail (−N), y = z × x along it, z up: the velocity and spin in that frame.</source>
        <translation>x a mantinelbe mutat (−N), y = z × x mentén fut, z felfelé mutat: a sebesség és a pörgés ebben a rendszerben.</translation>
    </message>
    <message>
        <source>Slip at the contact and approach</source>
        <translation>Csúszás az érintkezésnél és közeledés</translation>
    </message>
    <message>
        <source>How fast the ball&apos;s surface slides over the cushion at the contact point, and how fast it approaches along the contact normal.</source>
        <translation>Milyen gyorsan csúszik a golyó felülete a mantinelen az érintkezési pontban, és milyen gyorsan közeledik az érintkezési normális mentén.</translation>
    </message>
    <message>
        <source>Normal impulse PzE and stopping impulse PzS</source>
        <translation>A PzE normális és a PzS megállító erőlökés</translation>
    </message>
    <message>
        <source>Compression and restitution give the normal impulse PzE; PzS is the tangential impulse that would stop the slip (A = 7/(2m), B = 1/m).</source>
        <translation>Az összenyomódás és a visszarugózás adja a PzE normális erőlökést; PzS az az érintőleges erőlökés, amely megállítaná a csúszást (A = 7/(2m), B = 1/m).</translation>
    </message>
    <message>
        <source>Sticking: friction stops the slip</source>
        <translation>Tapadás: a súrlódás megállítja a csúszást</translation>
    </message>
    <message>
        <source>Sliding: friction at its Coulomb limit</source>
        <translation>Csúszás: a súrlódás a Coulomb-határán</translation>
    </message>
    <message>
        <source>P_{zS} ≤ μ P_{zE}: friction is strong enough to stop the slip, so the tangential impulse is exactly what stops it.</source>
        <translation>P_{zS} ≤ μ P_{zE}: a súrlódás elég erős a csúszás megállításához, így az érintőleges erőlökés pontosan annyi, amennyi megállítja.</translation>
    </message>
    <message>
        <source>P_{zS} &gt; μ P_{zE}: friction cannot stop the slip; it acts at its limit μ P_{zE} against the slip direction.</source>
        <translation>P_{zS} &gt; μ P_{zE}: a súrlódás nem tudja megállítani a csúszást; μ P_{zE} határértékén hat, a csúszás irányával szemben.</translation>
    </message>
    <message>
        <source>sticking</source>
        <translation>tapad</translation>
    </message>
    <message>
        <source>Impulse in the rail frame</source>
        <translation>Erőlökés a mantinel koordináta-rendszerében</translation>
    </message>
    <message>
        <source>The contact-frame impulse turned back by θ_a into the rail frame.</source>
        <translation>Az érintkezési rendszerbeli erőlökés θ_a szöggel visszaforgatva a mantinel rendszerébe.</translation>
    </message>
    <message>
        <source>Velocity and spin after</source>
        <translation>Sebesség és pörgés utána</translation>
    </message>
    <message>
        <source>Impulse over mass changes the velocity, its torque about the centre over I = 2/5 m R² the spin; back in the table frame. The ball leaves sliding.</source>
        <translation>Az erőlökés osztva a tömeggel megváltoztatja a sebességet, középpontra vett forgatónyomatéka osztva I = 2/5 m R²-tel a pörgést; vissza az asztal rendszerébe. A golyó csúszva távozik.</translation>
    </message>
    <message>
        <source>Two contacts: the cushion nose and the cloth</source>
        <translation>Két érintkezés: a mantinel éle és a posztó</translation>
    </message>
    <message>
        <source>The nose touches the ball at θ above the equator (I, its force along n_I towards the centre); the cloth holds the ball from below (C). Both rub during the impact: μ_w at the cushion, the cloth&apos;s μ_s under the ball.</source>
        <translation>Az él θ szöggel az egyenlítő fölött éri a golyót (I, ereje n_I mentén a középpont felé mutat); a posztó alulról tartja a golyót (C). Az ütközés alatt mindkettő súrlódik: a mantinelnél μ_w, a golyó alatt a posztó μ_s együtthatójával.</translation>
    </message>
    <message>
        <source>The impulse steps</source>
        <translation>Az erőlökés lépései</translation>
    </message>
    <message>
        <source>The normal impulse P at I is the clock of the impact. The paper integrates in equal steps dP: the expected total (1 + e) m v_n / cos θ split into N steps (the setup&apos;s `steps`).</source>
        <translation>Az ütközés óramutatója az I-ben ható P normális erőlökés. A cikk egyenlő dP lépésekben integrál: a várható (1 + e) m v_n / cos θ összeget N lépésre osztja (a beállítás `steps` értéke).</translation>
    </message>
    <message>
        <source>No approach</source>
        <translation>Nincs közeledés</translation>
    </message>
    <message>
        <source>The contact point does not move into the cushion: no impulse.</source>
        <translation>Az érintkezési pont nem mozdul a mantinel felé: nincs erőlökés.</translation>
    </message>
    <message>
        <source>Slip at both contacts before</source>
        <translation>Csúszás mindkét érintkezésnél előtte</translation>
    </message>
    <message>
        <source>How fast the ball&apos;s surface slides over the cushion at I and over the cloth at C. In every step friction acts against each slip, at its Coulomb limit (μ_w dP at I; μ_s times the cloth&apos;s normal impulse at C), or less if that would more than stop the slip (a friction impulse f changes its contact&apos;s slip by 7f/(2m)).</source>
        <translation>Milyen gyorsan csúszik a golyó felülete a mantinelen I-ben és a posztón C-ben. Minden lépésben a súrlódás mindkét csúszással szemben hat, a Coulomb-határán (I-ben μ_w dP; C-ben μ_s szorozva a posztó normális erőlökésével), vagy kevesebbel, ha az többet tenne, mint megállítani a csúszást (egy f súrlódási erőlökés 7f/(2m)-mel változtatja érintkezése csúszását).</translation>
    </message>
    <message>
        <source>Compression: until I stops approaching</source>
        <translation>Összenyomódás: amíg I már nem közeledik</translation>
    </message>
    <message>
        <source>Step by step, each step&apos;s friction directions those at its start, until ż_I reaches 0; the last step is cut where it does (ż_I is linear in dP within a step). W_c is the work of the normal force so far (trapezoidal, exact on a linear ż_I).</source>
        <translation>Lépésről lépésre, minden lépés súrlódási irányai a lépés elejéről valók, amíg ż_I el nem éri a 0-t; az utolsó lépést ott vágjuk el, ahol ez bekövetkezik (ż_I egy lépésen belül dP lineáris függvénye). W_c a normális erő eddigi munkája (trapézszabállyal, lineáris ż_I-re pontos).</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>lépés</translation>
    </message>
    <message>
        <source>I at μ_w</source>
        <translation>I a μ_w határon</translation>
    </message>
    <message>
        <source>I stopped</source>
        <translation>I megállt</translation>
    </message>
    <message>
        <source>C at μ_s</source>
        <translation>C a μ_s határon</translation>
    </message>
    <message>
        <source>C stopped</source>
        <translation>C megállt</translation>
    </message>
    <message>
        <source>Restitution: until e² of the work comes back</source>
        <translation>Visszarugózás: amíg a munka e²-szerese vissza nem tér</translation>
    </message>
    <message>
        <source>The same steps go on while the ball leaves the cushion, until the work the normal force returns is e² W_c (the energetic coefficient); the last step is cut where it is (the returned work is quadratic in dP within a step).</source>
        <translation>Ugyanezek a lépések folytatódnak, amíg a golyó elhagyja a mantinelt, egészen addig, amíg a normális erő által visszaadott munka e² W_c nem lesz (energetikai ütközési szám); az utolsó lépést ott vágjuk el, ahol ez bekövetkezik (a visszaadott munka egy lépésen belül dP másodfokú függvénye).</translation>
    </message>
    <message>
        <source>The integration&apos;s step cap was reached with the ball still pressing in: its normal velocity into the cushion is taken away (which only removes energy).</source>
        <translation>Az integrálás elérte a lépésszám felső korlátját, miközben a golyó még nyomta a mantinelt: a mantinel felé mutató normális sebességét elvesszük (ami csak energiát von el).</translation>
    </message>
    <message>
        <source>The sum of the steps&apos; impulses at I, with the cloth&apos;s, changed the velocity and the spin; the vertical part went into the cloth. The ball leaves as its slip says.</source>
        <translation>Az I-beli lépések erőlökéseinek összege, a posztóéval együtt, megváltoztatta a sebességet és a pörgést; a függőleges rész a posztóba ment. A golyó a csúszása szerinti állapotban távozik.</translation>
    </message>
    <message>
        <source>Mirror reflection with restitution</source>
        <translation>Tükrözés ütközési számmal</translation>
    </message>
    <message>
        <source>The normal component of the velocity is reversed and scaled by e; the component along the cushion and the spins are kept (angles from the normal obey tan(out) = tan(in)/e).</source>
        <translation>A sebesség normális összetevője megfordul, és e-szeresére csökken; a mantinel menti összetevő és a pörgések megmaradnak (a normálistól mért szögekre tan(ki) = tan(be)/e).</translation>
    </message>
    <message>
        <source>Contact at the equator</source>
        <translation>Érintkezés az egyenlítőn</translation>
    </message>
    <message>
        <source>As in pooltool, the ball meets the cushion at its equator, along the cushion&apos;s normal N. The velocity of the contact point splits into its approach v_n (&lt; 0 approaching) and its slip v_t.</source>
        <translation>A pooltoolhoz hasonlóan a golyó az egyenlítőjén, a mantinel N normálisa mentén éri a mantinelt. Az érintkezési pont sebessége v_n közeledésre (&lt; 0, ha közeledik) és v_t csúszásra bomlik.</translation>
    </message>
    <message>
        <source>Normal and tangential springs</source>
        <translation>Normális és érintőleges rugó</translation>
    </message>
    <message>
        <source>Time runs in units of 1/ω_n. The normal spring&apos;s force per unit effective mass is A sin t while it compresses (to t = π/2) and A cos((t − π/2)/e) while it unloads, stiffer by 1/e², so the contact leaves at −e v_n (ends at (1 + e) π/2). The tangential spring has frequency ω_t = r ω_n, its stiffness per unit effective mass κ = r²/β_t with β_t = 1 + m R²/I = 7/2.</source>
        <translation>Az idő 1/ω_n egységekben telik. A normális rugó egységnyi effektív tömegre jutó ereje összenyomódás közben A sin t (t = π/2-ig), tehermentesülés közben A cos((t − π/2)/e), 1/e²-szer merevebben, így az érintkezés −e v_n sebességgel válik el ((1 + e) π/2-kor ér véget). Az érintőleges rugó frekvenciája ω_t = r ω_n, egységnyi effektív tömegre jutó merevsége κ = r²/β_t, ahol β_t = 1 + m R²/I = 7/2.</translation>
    </message>
    <message>
        <source>Stick and slip</source>
        <translation>Tapadás és csúszás</translation>
    </message>
    <message>
        <source>At t = 0 the contact slips if its slip outruns what the growing friction limit can hold (v_t &gt; μ A/κ), else it sticks. A stick ends when the spring force reaches μ F_n (the contact then slips the way the spring pulls); a slip ends when the contact&apos;s velocity reaches what the spring alone would give (it then sticks, holding its deflection). Each switch time is a root of the phases&apos; closed forms (sampled, then bisected).</source>
        <translation>t = 0-kor az érintkezés csúszik, ha csúszása gyorsabb, mint amit a növekvő súrlódási határ megtarthat (v_t &gt; μ A/κ), különben tapad. A tapadás akkor ér véget, amikor a rugóerő eléri μ F_n-t (az érintkezés ekkor arra csúszik, amerre a rugó húzza); a csúszás akkor ér véget, amikor az érintkezés sebessége eléri azt, amit a rugó egymagában adna (ekkor tapad, és megtartja kitérését). Minden váltás időpontja a szakaszok zárt alakjainak egy gyöke (mintavételezve, majd felezéssel).</translation>
    </message>
    <message>
        <source>stick: v(t) = v₀ cos(r τ) − u₀ r sin(r τ);   slip: v(t) = v₀ ∓ μ β_t (P_n(t) − P_n(t₀))</source>
        <translation>tapadás: v(t) = v₀ cos(r τ) − u₀ r sin(r τ);   csúszás: v(t) = v₀ ∓ μ β_t (P_n(t) − P_n(t₀))</translation>
    </message>
    <message>
        <source>phases</source>
        <translation>szakaszok</translation>
    </message>
    <message>
        <source>stick_{%1}</source>
        <translation>tapadás_{%1}</translation>
    </message>
    <message>
        <source>chattering</source>
        <translation>pattogás</translation>
    </message>
    <message>
        <source>Impulses</source>
        <translation>Erőlökések</translation>
    </message>
    <message>
        <source>The normal impulse returns the approach e times; the tangential one changes the slip from v_t to v_t′ (at most |v_t|: a rounding guard keeps the tangential energy from growing).</source>
        <translation>A normális erőlökés a közeledést e-szeresen adja vissza; az érintőleges a csúszást v_t-ről v_t′-re változtatja (legfeljebb |v_t|-re: egy kerekítési őr megakadályozza, hogy az érintőleges energia nőjön).</translation>
    </message>
    <message>
        <source>The impulse over mass changes the velocity (its vertical part goes into the cloth), its torque about the centre over I = 2/5 m R² the spin.</source>
        <translation>Az erőlökés osztva a tömeggel megváltoztatja a sebességet (függőleges része a posztóba megy), középpontra vett forgatónyomatéka osztva I = 2/5 m R²-tel a pörgést.</translation>
    </message>
    <message>
        <source>The cut angle φ lies between a&apos;s path d (its velocity) and n: 0° a full hit, 30° a half-ball hit; the ball fraction f = 1 − sin φ is the share of b that a covers, seen along its path (1 full, 0.5 half, 0 a graze).</source>
        <translation>A φ vágási szög az a golyó d pályája (a sebessége) és n között mérhető: 0° telitalálat, 30° félgolyós találat; az f = 1 − sin φ golyóhányad azt adja meg, hogy a pályája mentén nézve a golyó b mekkora részét takarja (1 teli, 0,5 fél, 0 súrolás).</translation>
    </message>
    <message>
        <source>The law above leaves the balls parting slower than %1 m/s while the contact forces press them together (the cloth&apos;s friction closes the gap faster than their turning about each other, |v_t|²/d, opens it): they would only chatter, ever more weakly, into a lasting contact. The simulator drops that micro-bounce (a normal impulse ΔP takes the separation speed away, which only removes energy) and holds the pair: from here a contact force N ≥ 0 pushes along n, solved with the cloth&apos;s friction. Each ball takes the impulse by one rule: c = 1 sliding, 5/7 rolling (it keeps rolling; the cloth takes the rest), 0 at rest.</source>
        <translation>A fenti törvény után a golyók %1 m/s-nál lassabban távolodnak, miközben az érintkezési erők egymáshoz nyomják őket (a posztó súrlódása gyorsabban zárja a rést, mint ahogy egymás körüli fordulásuk, |v_t|²/d, nyitja): csak egyre gyengülő pattogással jutnának tartós érintkezésbe. A szimulátor ezt a mikropattogást elhagyja (egy normális irányú ΔP erőlökés elveszi a szétválási sebességet, ami csak energiát von el), és a párt együtt tartja: innentől egy N ≥ 0 érintkezési erő nyom n mentén, a posztó súrlódásával együtt megoldva. Az erőlökést minden golyó egyetlen szabály szerint veszi fel: c = 1 csúszva, 5/7 gurulva (tovább gurul; a többit a posztó veszi fel), 0 nyugalomban.</translation>
    </message>
    <message>
        <source>The law above leaves the ball leaving the cushion slower than %1 m/s while the contact force presses it in: it would only chatter into a lasting contact. The simulator drops that micro-bounce (a normal impulse ΔP takes the separation speed away, which only removes energy) and holds the ball against the cushion: from here the cushion&apos;s force N ≥ 0 pushes along N. The ball takes the impulse by one rule: c = 1 sliding, 5/7 rolling (it keeps rolling), 0 at rest.</source>
        <translation>A fenti törvény után a golyó %1 m/s-nál lassabban távolodik a mantineltől, miközben az érintkezési erő visszanyomja: csak pattogva jutna tartós érintkezésbe. A szimulátor ezt a mikropattogást elhagyja (egy normális irányú ΔP erőlökés elveszi a szétválási sebességet, ami csak energiát von el), és a golyót a mantinelhez szorítva tartja: innentől a mantinel N ≥ 0 ereje nyom N mentén. Az erőlökést a golyó egyetlen szabály szerint veszi fel: c = 1 csúszva, 5/7 gurulva (tovább gurul), 0 nyugalomban.</translation>
    </message>
    <message>
        <source>In the frame of the pair&apos;s centre of mass, which moves at V = P / (m_a + m_b), the momenta p* = m (v − V) are equal and opposite before and after; an elastic, frictionless collision only turns them.</source>
        <translation>A pár V = P / (m_a + m_b) sebességgel mozgó tömegközépponti rendszerében a p* = m (v − V) lendületek ütközés előtt és után is egyenlő nagyok és ellentétesek; egy rugalmas, súrlódásmentes ütközés csak elforgatja őket.</translation>
    </message>
    <message>
        <source>The vertical part: into the cloth</source>
        <translation>A függőleges rész: bele a posztóba</translation>
    </message>
    <message>
        <source>An elevated cue (θ &gt; 0) also pushes the ball down: the impulse F e has the vertical part −F sin θ, which gives the centre a downward velocity. The ball lies on the cloth, so the cloth answers at the same instant with a bounce (the next event): a steep, firm stroke makes the ball jump.</source>
        <translation>A megemelt dákó (θ &gt; 0) lefelé is nyomja a golyót: az F e impulzusnak −F sin θ függőleges része van, amely lefelé irányuló sebességet ad a középpontnak. A golyó a posztón fekszik, ezért a posztó ugyanabban a pillanatban egy pattanással felel (a következő esemény): meredek, határozott lökéstől a golyó ugrik.</translation>
    </message>
    <message>
        <source>Why now: the flight lands</source>
        <translation>Miért most: a repülés földet ér</translation>
    </message>
    <message>
        <source>Since t_{start} the ball has flown free: gravity alone acts on it (no cloth, so no friction and no rolling resistance; its spin does not change), so its centre&apos;s height above its resting height is a parabola in τ = t − t_{start}. It lands when the height is 0 again: the positive root of that quadratic. It is highest at τ = v_{z,0}/g when it starts upwards.</source>
        <translation>t_{start} óta a golyó szabadon repül: csak a gravitáció hat rá (nincs alatta posztó, így nincs súrlódás és gördülési ellenállás sem; a pörgése nem változik), ezért a középpontjának a nyugalmi magassága fölötti magassága parabola τ = t − t_{start} függvényében. Akkor ér földet, amikor a magasság ismét 0: ennek a másodfokú egyenletnek a pozitív gyökénél. Ha felfelé indul, τ = v_{z,0}/g-nél van a legmagasabban.</translation>
    </message>
    <message>
        <source>The bounces of ball %1 end</source>
        <translation>A(z) %1 golyó pattogása véget ér</translation>
    </message>
    <message>
        <source>Why now: the sum of the bounces</source>
        <translation>Miért most: a pattanások összege</translation>
    </message>
    <message>
        <source>At t_{start} the ball landed at w and nothing could meet it before its bounces die out, so the simulator summed them instead of taking each as an event. Bounce j sends it up at w e_t^j, and the flight after it lasts 2 w e_t^j / g: a geometric series, whose sum T is finite for e_t &lt; 1. After infinitely many bounces the ball is on the cloth for good, with z = v_z = 0, at t_{start} + T; its vertical kinetic energy m w²/2 is all lost.</source>
        <translation>t_{start}-kor a golyó w sebességgel ért földet, és semmi sem érhette el, mielőtt a pattanásai elhalnak, ezért a szimulátor összegezte őket ahelyett, hogy mindegyiket külön eseménynek venné. A j-edik pattanás w e_t^j sebességgel dobja fel, és az utána következő repülés 2 w e_t^j / g ideig tart: ez mértani sor, amelynek T összege e_t &lt; 1 esetén véges. Végtelen sok pattanás után a golyó végleg a posztón van, z = v_z = 0 mellett, t_{start} + T-kor; m w²/2 függőleges mozgási energiája teljesen elvész.</translation>
    </message>
    <message>
        <source>The series&apos; end changes no number: the bounces before it took the vertical energy.</source>
        <translation>A sor vége egyetlen számot sem változtat: a függőleges energiát az előtte lévő pattanások vették el.</translation>
    </message>
    <message>
        <source>The cloth answers the elevated cue: ball %1 bounces</source>
        <translation>A posztó felel a megemelt dákós lökésre: a(z) %1 golyó pattan</translation>
    </message>
    <message>
        <source>Ball %1 lands and bounces on the cloth</source>
        <translation>A(z) %1 golyó földet ér és pattan a posztón</translation>
    </message>
    <message>
        <source>Into the cloth</source>
        <translation>Bele a posztóba</translation>
    </message>
    <message>
        <source>The elevated cue drives the ball down as well as forward: its velocity just after the strike has a downward part w. The ball is on the cloth, so the cloth answers at once, at the same instant.</source>
        <translation>A megemelt dákó előre és lefelé is hajtja a golyót: a lökés utáni sebességének van egy w lefelé mutató része. A golyó a posztón fekszik, ezért a posztó azonnal, ugyanabban a pillanatban felel rá.</translation>
    </message>
    <message>
        <source>The bounce</source>
        <translation>A pattanás</translation>
    </message>
    <message>
        <source>The cloth pushes the ball up with the normal impulse P_n that sends it off at e_t times its landing speed, and its friction acts on the slip u = v + R (z × ω) of the contact point with at most μ_t P_n (the slip stops first if it is small: then 2/7 m |u| is enough). The friction P_t changes v by P_t/m and ω by R (−z × P_t)/I, I = 2/5 m R².</source>
        <translation>A posztó P_n normális impulzussal löki fel a golyót, amely a földet érési sebességének e_t-szeresével indítja el, és súrlódása legfeljebb μ_t P_n-nel hat az érintkezési pont u = v + R (z × ω) csúszására (ha a csúszás kicsi, előbb megáll: ehhez 2/7 m |u| elég). A P_t súrlódás v-t P_t/m-mel, ω-t R (−z × P_t)/I-vel változtatja meg, I = 2/5 m R².</translation>
    </message>
    <message>
        <source>On the cloth for good</source>
        <translation>Végleg a posztón</translation>
    </message>
    <message>
        <source>The rebound e_t w is so small that its flight, 2 e_t w / g, is below the resolution of the clock at t: the rest of the series is summed at once, and the ball stays on the cloth.</source>
        <translation>Az e_t w visszapattanás olyan kicsi, hogy a repülése, 2 e_t w / g, kisebb, mint amit az óra t-nél fel tud bontani: a sor hátralévő része egyszerre összegződik, és a golyó a posztón marad.</translation>
    </message>
    <message>
        <source>The next flight</source>
        <translation>A következő repülés</translation>
    </message>
    <message>
        <source>It leaves the cloth at v_z′ and flies free again: it rises for v_z′/g to the height v_z′²/(2g) and lands after 2 v_z′/g at the same speed v_z′, unless it meets a ball or a cushion first.</source>
        <translation>v_z′ sebességgel hagyja el a posztót, és ismét szabadon repül: v_z′/g ideig emelkedik v_z′²/(2g) magasságig, és 2 v_z′/g múlva ugyanazzal a v_z′ sebességgel ér földet, hacsak előbb nem ütközik golyóval vagy mantinellel.</translation>
    </message>
    <message>
        <source>All the bounces to come</source>
        <translation>Az összes hátralévő pattanás</translation>
    </message>
    <message>
        <source>Each bounce returns e_t of the landing speed, so the flights last 2 v_z′/g, 2 v_z′ e_t/g, 2 v_z′ e_t²/g, …: infinitely many, but a geometric series with a finite sum. Left alone, the ball is on the cloth for good after T, and the cloth has then taken all of this vertical kinetic energy.</source>
        <translation>Minden pattanás a földet érési sebesség e_t-szeresét adja vissza, így a repülések 2 v_z′/g, 2 v_z′ e_t/g, 2 v_z′ e_t²/g, … ideig tartanak: végtelen sok, de véges összegű mértani sor. Ha semmi sem zavarja, a golyó T múlva végleg a posztón van, és addigra a posztó elvette ezt az egész függőleges mozgási energiát.</translation>
    </message>
    <message>
        <source>The bounce takes (1 − e_t²) m w²/2 of the vertical kinetic energy, and friction what the slip loses.</source>
        <translation>A pattanás a függőleges mozgási energiából (1 − e_t²) m w²/2-t vesz el, a súrlódás pedig azt, amit a csúszás veszít.</translation>
    </message>
    <message>
        <source>Ball %1 leaves the table</source>
        <translation>A(z) %1 golyó elhagyja az asztalt</translation>
    </message>
    <message>
        <source>The ball flew over a cushion&apos;s nose, higher than the rail can stop, or came down where there is no cloth (beyond the cushions, on a rail&apos;s end): there is no table under it any more. It is out of play, like a pocketed ball, and is kept where it left with no motion and no energy.</source>
        <translation>A golyó magasabban repült át a mantinel élén, mint amit a keret megállíthat, vagy ott ért le, ahol nincs posztó (a mantineleken túl, egy keret végén): nincs már alatta asztal. Kiesett a játékból, mint egy lyukba esett golyó, és ott marad, ahol kiesett, mozgás és energia nélkül.</translation>
    </message>
    <message>
        <source>The ball takes all its kinetic energy off the table.</source>
        <translation>A golyó az összes mozgási energiáját magával viszi az asztalról.</translation>
    </message>
    <message>
        <source>f(τ) = z(t_0+τ)   (the height of the centre above its resting height)</source>
        <translation>f(τ) = z(t_0+τ)   (a középpont magassága a nyugalmi magassága fölött)</translation>
    </message>
    <message>
        <source>τ* is the positive root, where the height falls to 0 (f′(τ*) = −w &lt; 0: the ball comes down); the other root, at or before τ = 0, is where this parabola would have left the cloth.</source>
        <translation>τ* a pozitív gyök, ahol a magasság 0-ra csökken (f′(τ*) = −w &lt; 0: a golyó lefelé jön); a másik gyök, τ = 0-nál vagy előtte, az, ahol ez a parabola elhagyta volna a posztót.</translation>
    </message>
    <message>
        <source>The impulse F e moves the centre (its vertical part drives the ball into the cloth: the next step) and its torque Q × F e about the centre spins the ball: top spin for b &gt; 0, right english (ω_z &gt; 0) for a &gt; 0. The ball leaves %1.</source>
        <translation>Az F e erőlökés elmozdítja a középpontot (függőleges része a posztóba hajtja a golyót: lásd a következő lépést), a középpontra vett Q × F e forgatónyomatéka pedig megpörgeti a golyót: b &gt; 0 esetén felső pörgés, a &gt; 0 esetén jobb oldalpörgés (ω_z &gt; 0). A golyó ezután %1.</translation>
    </message>
    <message>
        <source>The cloth stops the ball&apos;s fall: this bounce and all the ones after it, too short for the clock to tell apart, are taken at once. Together they change the vertical momentum by P_n = m w (the cloth&apos;s impulses, (1 + e_t)/(1 − e_t) m w in all, less gravity&apos;s over their time), and their friction on the slip u = v + R (z × ω) of the contact point adds up to at most μ_t (1 + e_t)/(1 − e_t) m w (the slip stops first if it is small: then 2/7 m |u| is enough). The friction P_t changes v by P_t/m and ω by R (−z × P_t)/I, I = 2/5 m R².</source>
        <translation>A posztó megállítja a golyó esését: ezt a pattanást és az összes utána következőt, amelyeket az óra már nem tud szétválasztani, egyszerre veszi. Együtt P_n = m w-vel változtatják meg a függőleges lendületet (a posztó impulzusai összesen (1 + e_t)/(1 − e_t) m w, ebből levonva a gravitációé az idejük alatt), súrlódásuk pedig az érintkezési pont u = v + R (z × ω) csúszására összesen legfeljebb μ_t (1 + e_t)/(1 − e_t) m w (ha a csúszás kicsi, előbb megáll: ehhez 2/7 m |u| elég). A P_t súrlódás v-t P_t/m-mel, ω-t R (−z × P_t)/I-vel változtatja meg, I = 2/5 m R².</translation>
    </message>
    <message>
        <source>Since t_{start} %1 has been %2: it turns on the spot about the vertical, and its centre does not move (v = 0, a = 0).</source>
        <translation>t_{start} óta a(z) %1 golyó %2: helyben forog a függőleges tengely körül, a középpontja nem mozdul (v = 0, a = 0).</translation>
    </message>
    <message>
        <source>Since t_{start} %1 has been %2: its centre does not move (v = 0, a = 0).</source>
        <translation>t_{start} óta a(z) %1 golyó %2: a középpontja nem mozdul (v = 0, a = 0).</translation>
    </message>
    <message>
        <source>Since t_{start} %1 has been in the air, held against a ball it presses on: besides gravity the contact force per unit mass q acts on it, constant over the segment, so its centre moves on a parabola in space with the constant acceleration a = q − g z; its spin does not change (no cloth, no friction).</source>
        <translation>t_{start} óta a(z) %1 golyó a levegőben van, és egy golyóhoz szorul, amelyre ránehezedik: a gravitáció mellett az egységnyi tömegre jutó q érintkezési erő is hat rá, amely a szakaszon állandó, így középpontja a térben parabolán mozog, állandó a = q − g z gyorsulással; a pörgése nem változik (nincs posztó, nincs súrlódás).</translation>
    </message>
    <message>
        <source>Since t_{start} %1 has been in the air: gravity alone acts on it, so its centre moves on a parabola in space, uniformly across the table and falling with the constant acceleration g (a = −g z); its spin does not change (no cloth, no friction).</source>
        <translation>t_{start} óta a(z) %1 golyó a levegőben van: csak a gravitáció hat rá, így középpontja a térben parabolán mozog, az asztal síkjában egyenletesen, függőlegesen állandó g gyorsulással esve (a = −g z); a pörgése nem változik (nincs posztó, nincs súrlódás).</translation>
    </message>
    <message>
        <source>Ball-jaw collision of %1 with %2 in the air</source>
        <translation>Golyó–pofa ütközés a levegőben: %1 golyó – %2</translation>
    </message>
    <message>
        <source>Ball-cushion collision of %1 with %2 in the air</source>
        <translation>Golyó–mantinel ütközés a levegőben: %1 golyó – %2</translation>
    </message>
    <message>
        <source>the impact law of a flying ball</source>
        <translation>a repülő golyó ütközési törvénye</translation>
    </message>
    <message>
        <source>f(τ) = (r(t_0+τ) − p_a)·N − R   (the centre&apos;s distance from the cushion&apos;s face, minus R; the centre at or below the nose)</source>
        <translation>f(τ) = (r(t_0+τ) − p_a)·N − R   (a középpont távolsága a mantinel homlokától, mínusz R; a középpont az él magasságában vagy alatta)</translation>
    </message>
    <message>
        <source>f(τ) = n(τ)^2 + (z_c(τ) − h)^2 − R^2   (the squared distance of the centre from the nose edge, n its distance in front of the nose line, z_c its height, h the nose&apos;s)</source>
        <translation>f(τ) = n(τ)^2 + (z_c(τ) − h)^2 − R^2   (a középpont és a mantinel éle közti távolság négyzete; n a középpont távolsága az él egyenese előtt, z_c a magassága, h az élé)</translation>
    </message>
    <message>
        <source>f(τ) = |r(t_0+τ) − p_{end}|^2 − R^2   (the corner&apos;s vertical edge at the segment&apos;s end)</source>
        <translation>f(τ) = |r(t_0+τ) − p_{end}|^2 − R^2   (a sarok függőleges éle a szakasz végén)</translation>
    </message>
    <message>
        <source>f(τ) = |c(t_0+τ) − (p_{end}, h)|^2 − R^2   (the top corner at the segment&apos;s end, at the nose&apos;s height h)</source>
        <translation>f(τ) = |c(t_0+τ) − (p_{end}, h)|^2 − R^2   (a felső sarok a szakasz végén, az él h magasságában)</translation>
    </message>
    <message>
        <source>f(τ) = z_c(t_0+τ) − (h + R)   (the centre R above the jaw&apos;s flat top)</source>
        <translation>f(τ) = z_c(t_0+τ) − (h + R)   (a középpont R-rel a pofa lapos teteje fölött)</translation>
    </message>
    <message>
        <source>(ρ(τ) − r_{jaw})^2 + (z_c(τ) − h)^2 = R^2   (the centre R from the jaw&apos;s rim; ρ its horizontal distance from the tip&apos;s axis: of degree eight in τ)</source>
        <translation>(ρ(τ) − r_{jaw})^2 + (z_c(τ) − h)^2 = R^2   (a középpont R-re van a pofa peremétől; ρ a vízszintes távolsága a pofa tengelyétől: τ-ban nyolcadfokú)</translation>
    </message>
    <message>
        <source>The ball was already touching it (within 10^{−10} m) and approaching or pressed on it: the contact begins at that instant, not at a root of f.</source>
        <translation>A golyó már érintette (10^{−10} m-en belül), és közeledett felé vagy rá volt szorulva: az érintkezés abban a pillanatban kezdődik, nem f egy gyökénél.</translation>
    </message>
    <message>
        <source>τ* is the first instant in the flight at which the centre comes within R of the rim, approaching it.</source>
        <translation>τ* a repülés első olyan pillanata, amikor a középpont a peremhez közeledve R távolságra kerül tőle.</translation>
    </message>
    <message>
        <source>τ* is the smallest root in the flight 0 &lt; τ ≤ H at which f falls (the ball approaches) with the centre where this part of the body is met (in front of the nose line, on the segment, above or below the nose as the part says).</source>
        <translation>τ* a 0 &lt; τ ≤ H repülés legkisebb olyan gyöke, ahol f csökken (a golyó közeledik), és a középpont ott van, ahol a testnek ezt a részét érheti (az él egyenese előtt, a szakasz mentén, az él fölött vagy alatt, ahogy az adott rész kívánja).</translation>
    </message>
    <message>
        <source>The ball flies low enough to meet the cushion&apos;s face, below its nose.</source>
        <translation>A golyó elég alacsonyan repül ahhoz, hogy a mantinel homlokát az éle alatt érje el.</translation>
    </message>
    <message>
        <source>The ball comes down on the cushion&apos;s nose edge from above it.</source>
        <translation>A golyó felülről érkezik a mantinel élére.</translation>
    </message>
    <message>
        <source>Past the end of the segment, the ball meets the corner&apos;s vertical edge there.</source>
        <translation>A szakasz végén túl a golyó az ottani sarok függőleges élét éri el.</translation>
    </message>
    <message>
        <source>Past the end of the segment, the ball meets the top corner there, at the nose&apos;s height.</source>
        <translation>A szakasz végén túl a golyó az ottani felső sarkot éri el, az él magasságában.</translation>
    </message>
    <message>
        <source>The ball meets the jaw&apos;s side (a vertical cylinder of radius r_{jaw} up to the nose&apos;s height).</source>
        <translation>A golyó a pofa oldalát éri el (egy r_{jaw} sugarú függőleges hengert az él magasságáig).</translation>
    </message>
    <message>
        <source>The ball comes down on the jaw&apos;s flat top.</source>
        <translation>A golyó a pofa lapos tetejére érkezik.</translation>
    </message>
    <message>
        <source>The ball meets the jaw&apos;s rim, the circle where its side meets its top.</source>
        <translation>A golyó a pofa peremét éri el: azt a kört, ahol az oldala a tetejével találkozik.</translation>
    </message>
    <message>
        <source>Contact geometry in space</source>
        <translation>Az érintkezés geometriája a térben</translation>
    </message>
    <message>
        <source>The normal n points from the body&apos;s contact towards the ball&apos;s centre; the contact lies R behind the centre along −n (r_c is its place seen from above, N the direction of n&apos;s level part). The ball approaches when v·n &lt; 0.</source>
        <translation>Az n normális a test érintkezési pontjától a golyó középpontja felé mutat; az érintkezési pont R-rel a középpont mögött van −n irányában (r_c a helye felülről nézve, N az n vízszintes részének iránya). A golyó közeledik, ha v·n &lt; 0.</translation>
    </message>
    <message>
        <source>The contact is level with the centre: n_z = 0.</source>
        <translation>Az érintkezési pont a középponttal egy magasságban van: n_z = 0.</translation>
    </message>
    <message>
        <source>The impact</source>
        <translation>Az ütközés</translation>
    </message>
    <message>
        <source>A single impulse at the contact: Newton&apos;s restitution along n (the cushion&apos;s e), and friction against the slip u_t of the contact point across n, at most μ P_n and never more than stops it (any tangent of a solid sphere takes 7/2 of the impulse over m). The normal part acts through the centre; the friction also turns the ball by Q × P_t / I.</source>
        <translation>Egyetlen impulzus az érintkezési pontban: Newton-féle restitúció n mentén (a mantinel e tényezőjével), és súrlódás az érintkezési pont n-re merőleges u_t csúszása ellen, legfeljebb μ P_n, és sosem több, mint ami megállítja (tömör gömb bármely érintőirányban az impulzus m-re jutó részének 7/2-szeresét veszi fel). A normális rész a középponton át hat; a súrlódás Q × P_t / I-vel meg is forgatja a golyót.</translation>
    </message>
    <message>
        <source>v′ = v + J/m and ω′ = ω + Q × P_t / I: the states the simulation goes on from.</source>
        <translation>v′ = v + J/m és ω′ = ω + Q × P_t / I: ezekből az állapotokból folytatódik a szimuláció.</translation>
    </message>
    <message>
        <source>The ball is pressed on the face by the balls it is held with: the face joins their group as a row, solved with the others, and the parting speed the law leaves is taken away. These are the states the simulation goes on from.</source>
        <translation>A golyót azok a golyók szorítják a homlokhoz, amelyekkel tartósan érintkezik: a homlok sorként csatlakozik a csoportjukhoz, a többivel együtt oldjuk meg, és a törvény meghagyta távolodási sebességet elvesszük. Ezekből az állapotokból folytatódik a szimuláció.</translation>
    </message>
    <message>
        <source>The law leaves the ball parting slower than %1 m/s while gravity presses it on: it would bounce ever lower on the edge. It is held there instead, the rebound taken away (which only removes energy); from here a contact force N ≥ 0 along n holds it. These are the states the simulation goes on from.</source>
        <translation>A törvény után a golyó %1 m/s-nál lassabban távolodna, miközben a gravitáció ránehezíti: egyre kisebbeket pattanna az élen. Ehelyett ott tartjuk, a visszapattanást elvéve (ez csak energiát von el); innentől egy n menti N ≥ 0 érintkezési erő tartja. Ezekből az állapotokból folytatódik a szimuláció.</translation>
    </message>
    <message>
        <source>The ball joins the group of contacts it is held in, and their rows are solved together: these are the states the simulation goes on from.</source>
        <translation>A golyó csatlakozik a tartós érintkezések csoportjához, amelyben van, és a sorokat együtt oldjuk meg: ezekből az állapotokból folytatódik a szimuláció.</translation>
    </message>
    <message>
        <source>After the collision</source>
        <translation>Az ütközés után</translation>
    </message>
    <message>
        <source>The body pushes the ball: the change of its momentum in space is the body&apos;s impulse J.</source>
        <translation>A test meglöki a golyót: lendületének térbeli változása a test J impulzusa.</translation>
    </message>
    <message>
        <source>The cloth answers %1</source>
        <translation>A posztó válasza: %1</translation>
    </message>
    <message>
        <source>%1 lies on the cloth, and the impulse drives it down into it at w = −v_z: the cloth answers at once, as it answers a landing. Its normal impulse (1 + e_t) m w sends the ball up at e_t w, and its friction acts on the slip of the contact point, at most μ_t times that (less if the slip stops first: 2/7 m |u|).</source>
        <translation>A(z) %1 golyó a posztón fekszik, és az impulzus w = −v_z sebességgel a posztóba nyomja: a posztó azonnal válaszol, ahogy egy földet érésre. (1 + e_t) m w normális impulzusa e_t w sebességgel löki fel a golyót, súrlódása pedig az érintkezési pont csúszására hat, legfeljebb ennek μ_t-szeresével (kevesebbel, ha a csúszás előbb megáll: 2/7 m |u|).</translation>
    </message>
    <message>
        <source>The rebound would lift it less than %1 m off the cloth: the cloth keeps it down (v_z = 0), and the rebound&apos;s vertical speed goes into the cloth.</source>
        <translation>A visszapattanás %1 m-nél kevésbé emelné el a posztótól: a posztó lent tartja (v_z = 0), és a visszapattanás függőleges sebességét a posztó nyeli el.</translation>
    </message>
    <message>
        <source>The cloth keeps %1</source>
        <translation>A posztó lent tartja: %1</translation>
    </message>
    <message>
        <source>The impulse sends %1, which lies on the cloth, up at v_z so slowly that its hop would stay within %2 m of the cloth (v_z² / 2g): the cloth keeps it down (v_z = 0), and its vertical speed goes into the cloth, as a landing&apos;s.</source>
        <translation>Az impulzus a posztón fekvő %1 golyót olyan lassan, v_z sebességgel indítja felfelé, hogy ugrása %2 m-en belül maradna (v_z² / 2g): a posztó lent tartja (v_z = 0), és függőleges sebességét a posztó nyeli el, mint egy földet érésnél.</translation>
    </message>
    <message>
        <source>Ball-ball collision of %1 and %2 in the air</source>
        <translation>Golyó–golyó ütközés a levegőben: %1 és %2</translation>
    </message>
    <message>
        <source>The balls touch when their centres are R_a + R_b apart in space (a = %1, b = %2); a centre is at the height R + z above the cloth.</source>
        <translation>A golyók akkor érintkeznek, amikor középpontjaik távolsága a térben R_a + R_b (a = %1, b = %2); egy középpont R + z magasan van a posztó fölött.</translation>
    </message>
    <message>
        <source>Both balls fly, and the same gravity pulls both down, so it cancels in c_b − c_a: their difference moves uniformly.</source>
        <translation>Mindkét golyó repül, és ugyanaz a gravitáció húzza le őket, így c_b − c_a-ban kiesik: a különbségük egyenletesen mozog.</translation>
    </message>
    <message>
        <source>The normal n points from the centre of a to the centre of b in space; it leaves the cloth&apos;s plane by the difference of their heights. The contact point lies R_a along it (r_c is its place seen from above, n_h the direction of n&apos;s level part). The balls approach when their relative velocity in space along n is positive.</source>
        <translation>Az n normális a térben az a golyó középpontjából a b golyó középpontja felé mutat; magasságuk különbségével kilép a posztó síkjából. Az érintkezési pont R_a távolságra van rajta (r_c a helye felülről nézve, n_h az n vízszintes részének iránya). A golyók közelednek, ha térbeli relatív sebességük n menti része pozitív.</translation>
    </message>
    <message>
        <source>Here both centres are at the same height: n is level, n_z = 0.</source>
        <translation>Itt a két középpont egy magasságban van: n vízszintes, n_z = 0.</translation>
    </message>
    <message>
        <source>Normal impulse</source>
        <translation>Normális impulzus</translation>
    </message>
    <message>
        <source>Newton&apos;s restitution along the normal in space: the balls part along n at e times the speed they approach with. Both are free in space, so each takes the impulse with its own mass. The impulse on a is −P_n n: its vertical part −P_n n_z lifts or presses a ball as much as the tilt of n says.</source>
        <translation>Newton-féle restitúció a térbeli normális mentén: a golyók n mentén a közeledési sebességük e-szeresével távolodnak. Mindkettő szabad a térben, így mindegyik a saját tömegével veszi fel az impulzust. Az a-ra ható impulzus −P_n n: függőleges része, −P_n n_z, annyira emeli vagy nyomja le a golyót, amennyire n dől.</translation>
    </message>
    <message>
        <source>Friction between the balls</source>
        <translation>Súrlódás a golyók között</translation>
    </message>
    <message>
        <source>The contact points slip across each other at u_t (their velocities v + ω × (±R n), less the part along n). Friction acts against it with at most μ P_n, and never more than stops the slip (a solid sphere&apos;s tangential compliance is 7/2 (1/m_a + 1/m_b)). It changes each ball&apos;s spin by (R n) × J_t / I.</source>
        <translation>Az érintkezési pontok u_t sebességgel csúsznak el egymáson (v + ω × (±R n) sebességük, n menti részük nélkül). A súrlódás ez ellen hat, legfeljebb μ P_n-nel, és sosem jobban, mint ami megállítja a csúszást (tömör gömbök érintőirányú engedékenysége 7/2 (1/m_a + 1/m_b)). Mindkét golyó pörgését (R n) × J_t / I-vel változtatja.</translation>
    </message>
    <message>
        <source>The contact points do not slip across each other (u_t = 0): friction has nothing to act on, J_t = 0.</source>
        <translation>Az érintkezési pontok nem csúsznak el egymáson (u_t = 0): a súrlódásnak nincs min hatnia, J_t = 0.</translation>
    </message>
    <message>
        <source>Velocities after the impulse</source>
        <translation>Sebességek az impulzus után</translation>
    </message>
    <message>
        <source>Each ball&apos;s velocity in space changes by its impulse over its mass (b takes −J); the spins by the friction&apos;s torque alone, since the normal impulse acts through both centres.</source>
        <translation>Mindkét golyó térbeli sebessége az impulzusa és a tömege hányadosával változik (b −J-t kap); a pörgések csak a súrlódás forgatónyomatéka szerint, mert a normális impulzus mindkét középponton át hat.</translation>
    </message>
    <message>
        <source>These are the states the simulation goes on from.</source>
        <translation>Ezekből az állapotokból folytatódik a szimuláció.</translation>
    </message>
    <message>
        <source>The law leaves the pair parting slower than %1 m/s (or touching with no approach) while the upper ball&apos;s weight presses it on the other: it would only bounce ever lower on it. The pair is held instead: the re-seating takes the parting speed away (which only removes energy), and from here a contact force N ≥ 0 along n keeps the balls touching, solved with gravity and the cloth&apos;s friction. These are the states the simulation goes on from.</source>
        <translation>A törvény után a pár %1 m/s-nál lassabban távolodna (vagy közeledés nélkül érintkezik), miközben a felső golyó súlya a másikra nyomja: csak egyre kisebbeket pattanna rajta. Ehelyett a párt tartósan érintkezőnek vesszük: az újraillesztés elveszi a távolodási sebességet (ez csak energiát von el), és innentől egy n menti N ≥ 0 érintkezési erő tartja össze a golyókat, a gravitációval és a posztó súrlódásával együtt megoldva. Ezekből az állapotokból folytatódik a szimuláció.</translation>
    </message>
    <message>
        <source>The pair joins the balls it is held with: their contacts are solved together, and what relative normal speed the others have left is taken away at the same time. These are the states the simulation goes on from.</source>
        <translation>A pár csatlakozik azokhoz a golyókhoz, amelyekkel tartósan érintkezik: érintkezéseiket együtt oldjuk meg, és a többiek megmaradt relatív normális sebességét ugyanabban a lépésben elvesszük. Ezekből az állapotokból folytatódik a szimuláció.</translation>
    </message>
    <message>
        <source>The balls touch with no approach: the ball on the cloth goes on as its slip says (a slip of rounding rolled out, a roll slower than the cloth can tell stopped). These are the states the simulation goes on from.</source>
        <translation>A golyók közeledés nélkül érintkeznek: a posztón lévő golyó a csúszása szerint halad tovább (a kerekítésből adódó csúszás kigördül, a posztó számára kimérhetetlenül lassú gördülés megáll). Ezekből az állapotokból folytatódik a szimuláció.</translation>
    </message>
    <message>
        <source>The collision turns some energy into sound and heat (restitution e &lt; 1, friction); a ball the impulse drives into the cloth loses more there.</source>
        <translation>Az ütközés az energia egy részét hanggá és hővé alakítja (restitúció e &lt; 1, súrlódás); az a golyó, amelyet az impulzus a posztóba nyom, ott még többet veszít.</translation>
    </message>
    <message>
        <source>The impulses between the balls are equal and opposite, so they keep the pair&apos;s momentum in space; gravity adds nothing in an instant. Only the cloth&apos;s answer to a ball on it changes it: ΔP = P_{cloth}.</source>
        <translation>A golyók közti impulzusok egyenlők és ellentétesek, így a pár térbeli lendülete megmarad; a gravitáció egy pillanat alatt semmit sem ad hozzá. Csak a posztó válasza egy rajta fekvő golyóra változtatja meg: ΔP = P_{cloth}.</translation>
    </message>
    <message>
        <source>Here no ball is driven into the cloth: P_{cloth} = 0.</source>
        <translation>Itt egyik golyót sem nyomja az impulzus a posztóba: P_{cloth} = 0.</translation>
    </message>
    <message>
        <source>The hold&apos;s impulses come on top.</source>
        <translation>Ehhez jönnek még a tartós érintkezés impulzusai.</translation>
    </message>
    <message>
        <source>The bodies were touching at the event (within 10^{−10} m), grazing, approaching or pressed together (a group of held contacts solved again then): the contact begins at that instant, not at a root of f.</source>
        <translation>A testek az eseménykor érintkeztek (10^{−10} m-en belül): súrolták egymást, közeledtek vagy egymáshoz szorultak (a tartós érintkezések egy csoportját ekkor oldottuk meg újra): az érintkezés abban a pillanatban kezdődik, nem f egy gyökénél.</translation>
    </message>
    <message>
        <source>The ball was already touching the cushion&apos;s line, beyond the end of this segment, and closing in: the contact begins where the foot of the perpendicular from its centre enters the segment through its end (λ = 0 or 1), not at a root of f.</source>
        <translation>A golyó már érintette a mantinel egyenesét, ennek a szakasznak a végén túl, és közeledett: az érintkezés ott kezdődik, ahol a középpontjából bocsátott merőleges talppontja a végén át belép a szakaszba (λ = 0 vagy 1), nem f egy gyökénél.</translation>
    </message>
    <message>
        <source>The simulator met this contact from a later instant of the paths: the same polynomial, written from t_0, rounds its root a little differently. τ* is the event&apos;s own time.</source>
        <translation>A szimulátor ezt az érintkezést a pályák egy későbbi pillanatából számolta: ugyanez a polinom t_0-tól felírva kissé másképp kerekíti a gyökét. τ* az esemény saját ideje.</translation>
    </message>
    <message>
        <source>Here f is linear in τ (degree 1)</source>
        <translation>Itt f τ-ban lineáris (elsőfokú)</translation>
    </message>
    <message>
        <source>Here f is a quadratic in τ (degree 2)</source>
        <translation>Itt f τ-ban másodfokú</translation>
    </message>
    <message>
        <source>Here f is a cubic in τ (degree 3)</source>
        <translation>Itt f τ-ban harmadfokú</translation>
    </message>
    <message>
        <source>Here f is a quartic in τ (degree 4)</source>
        <translation>Itt f τ-ban negyedfokú</translation>
    </message>
    <message>
        <source>Here f is constant</source>
        <translation>Itt f állandó</translation>
    </message>
    <message>
        <source>%1, with no real root.</source>
        <translation>%1, valós gyöke nincs.</translation>
    </message>
    <message>
        <source>%1, with one real root.</source>
        <translation>%1, egy valós gyöke van.</translation>
    </message>
    <message>
        <source>%1, with %2 real roots.</source>
        <translation>%1, %2 valós gyöke van.</translation>
    </message>
    <message>
        <source>The balls were already touching at the event (within 10^{−10} m) and approaching or pressed together: the contact begins at that instant, not at a root of f.</source>
        <translation>A golyók az eseménykor már érintkeztek (10^{−10} m-en belül), és közeledtek vagy egymáshoz szorultak: az érintkezés abban a pillanatban kezdődik, nem f egy gyökénél.</translation>
    </message>
    <message>
        <source>The balls were touching at t_0 (within 10^{−10} m) and approaching, or pressed together: the contact begins at once (τ = 0).</source>
        <translation>A golyók t_0-kor érintkeztek (10^{−10} m-en belül) és közeledtek, vagy egymáshoz szorultak: az érintkezés azonnal kezdődik (τ = 0).</translation>
    </message>
    <message>
        <source>τ* is the smallest root in the prediction window 0 &lt; τ ≤ H at which f falls (f′(τ) &lt; 0: the balls approach); a root where f rises (they part) or only touches zero (a graze) is passed over.</source>
        <translation>τ* a 0 &lt; τ ≤ H előrejelzési ablak legkisebb olyan gyöke, ahol f csökken (f′(τ) &lt; 0: a golyók közelednek); azt a gyököt, ahol f nő (a golyók távolodnak), vagy ahol csak érinti a nullát (súrolás), átugorjuk.</translation>
    </message>
    <message>
        <source>τ* is where the height falls to 0, the flight&apos;s landing: there the centre is over the pocket&apos;s circle, |r − c| &lt; r_{pocket}, so there is no cloth to land on.</source>
        <translation>τ* ott van, ahol a magasság 0-ra csökken, a repülés földet érésénél: ott a középpont a lyuk köre fölött van, |r − c| &lt; r_{pocket}, így nincs posztó, amelyre leérkezhetne.</translation>
    </message>
    <message>
        <source>The ball met the end of the rail inside the pocket&apos;s circle, lower than the rail&apos;s top: it drops in there, at the instant of that contact (not a root of the height).</source>
        <translation>A golyó a lyuk körén belül, a mantinel tetejénél alacsonyabban érte el a mantinel végét: ott, annak az érintkezésnek a pillanatában esik be (ez nem a magasság gyöke).</translation>
    </message>
    <message>
        <source>A flying ball drops into a pocket when it comes down to the cloth&apos;s level with its centre over the pocket&apos;s circle (centre c, radius r_{pocket}).</source>
        <translation>A repülő golyó akkor esik lyukba, amikor a posztó szintjére ereszkedik úgy, hogy középpontja a lyuk köre fölött van (középpontja c, sugara r_{pocket}).</translation>
    </message>
    <message>
        <source>Over the pocket</source>
        <translation>A lyuk fölött</translation>
    </message>
    <message>
        <source>Where it comes down, the centre is within r_{pocket} of the pocket&apos;s centre.</source>
        <translation>Ahol leérkezik, ott a középpont r_{pocket}-nél közelebb van a lyuk középpontjához.</translation>
    </message>
    <message>
        <source>The ball drops when its centre enters the pocket circle (centre c, radius r_{pocket}).</source>
        <translation>A golyó akkor esik be, amikor középpontja belép a lyuk körébe (középpontja c, sugara r_{pocket}).</translation>
    </message>
    <message>
        <source>Since t_{start} the ball has flown held against a ball it presses on: besides gravity the contact force&apos;s vertical part q_z per unit mass holds it up, so it falls with g − q_z (written g below), and its centre&apos;s height above its resting height is a parabola in τ = t − t_{start}. It lands when the height is 0 again: the positive root of that quadratic.</source>
        <translation>t_{start} óta a golyó egy golyóhoz szorulva repül, amelyre ránehezedik: a gravitáció mellett az érintkezési erő egységnyi tömegre jutó q_z függőleges része tartja, így g − q_z gyorsulással esik (lent ezt írjuk g-nek), és középpontjának a nyugalmi magassága fölötti magassága parabola τ = t − t_{start} függvényében. Akkor ér földet, amikor a magasság ismét 0: ennek a másodfokú egyenletnek a pozitív gyökénél.</translation>
    </message>
    <message>
        <source>(The simulator found the contact&apos;s normal from its own instant of prediction, which rounds it a little differently: its states, given here, agree with the law&apos;s above to within 10^{−9} of their size.)</source>
        <translation>(A szimulátor az érintkezés normálisát a saját előrejelzési pillanatából számolta, ami kissé másképp kerekíti: az itt megadott állapotai a fenti törvényéivel méretük 10^{−9}-szeresén belül egyeznek.)</translation>
    </message>
    <message>
        <source>No row needs a value: every λ = 0 satisfies the conditions.</source>
        <translation>Egyik sornak sem kell érték: minden λ = 0 teljesíti a feltételeket.</translation>
    </message>
    <message>
        <source>Found by pivoting: rows join the active set while their w would be negative and leave it while their λ would be; the active rows&apos; equations A_s λ_s = −b_s are solved by a pivoted LDLᵀ factorisation.</source>
        <translation>Pivotálással adódik: egy sor belép az aktív halmazba, amíg w-je negatív lenne, és kilép, amíg λ-ja az lenne; az aktív sorok A_s λ_s = −b_s egyenleteit pivotált LDLᵀ-felbontás oldja meg.</translation>
    </message>
    <message>
        <source>Found by pivoting; the active rows are dependent (more contacts than the balls have directions to move in, as in a packed cluster), so their equations are solved by the basic solution of the pivoted LDLᵀ factorisation, with no value on the dependent rows.</source>
        <translation>Pivotálással adódik; az aktív sorok összefüggők (több az érintkezés, mint ahány irányban a golyók mozoghatnak, mint egy szoros csoportban), ezért egyenleteiket a pivotált LDLᵀ-felbontás bázismegoldása oldja meg, az összefüggő sorokon érték nélkül.</translation>
    </message>
    <message>
        <source>Found by pivoting; the active rows&apos; equations have no exact solution (nearly parallel normals), so they are solved in the least-squares sense.</source>
        <translation>Pivotálással adódik; az aktív sorok egyenleteinek nincs pontos megoldása (közel párhuzamos normálisok), ezért legkisebb négyzetes értelemben oldódnak meg.</translation>
    </message>
    <message>
        <source>The pivoting ran out of steps: the values are those of the projected Gauss-Seidel iteration, complementary only approximately.</source>
        <translation>A pivotálás kifogyott a lépésekből: az értékek a vetített Gauss–Seidel-iteráció értékei, a komplementaritás csak közelítőleg teljesül.</translation>
    </message>
    <message>
        <source>row %1 active</source>
        <translation>%1. sor aktív</translation>
    </message>
    <message>
        <source>The details of the group&apos;s solve (its contacts as the rows of one problem, the impulses and forces that solve it) are left out: they come from running the shot again up to this event, and that took longer than %1 s.</source>
        <translation>A csoport megoldásának részletei (érintkezései mint egyetlen feladat sorai, az azt megoldó impulzusok és erők) kimaradnak: ezek a lökés újrafuttatásából származnak eddig az eseményig, és ez tovább tartott %1 s-nál.</translation>
    </message>
    <message>
        <source>The details of the group&apos;s solve (its contacts as the rows of one problem, the impulses and forces that solve it) are left out: running the shot again up to this event was stopped.</source>
        <translation>A csoport megoldásának részletei (érintkezései mint egyetlen feladat sorai, az azt megoldó impulzusok és erők) kimaradnak: a lökés újrafuttatása eddig az eseményig leállt.</translation>
    </message>
    <message>
        <source>The held group&apos;s solve</source>
        <translation>A tartott csoport megoldása</translation>
    </message>
    <message>
        <source>The other steps, from the event&apos;s own states, stand.</source>
        <translation>A többi lépés, amely az esemény saját állapotaiból indul, érvényes.</translation>
    </message>
    <message>
        <source>the event&apos;s own contact</source>
        <translation>az esemény saját érintkezése</translation>
    </message>
    <message>
        <source>held before</source>
        <translation>már korábban is tartott</translation>
    </message>
    <message>
        <source>touching, joins now</source>
        <translation>érintkezik, most csatlakozik</translation>
    </message>
    <message>
        <source>row %1: %2 and %3, n = (%4), %5, v_n = %6 m/s, %7</source>
        <translation>%1. sor: %2 és %3, n = (%4), %5, v_n = %6 m/s, %7</translation>
    </message>
    <message>
        <source>in space (a ball in the air)</source>
        <translation>a térben (levegőben lévő golyó)</translation>
    </message>
    <message>
        <source>on the cloth</source>
        <translation>a posztón</translation>
    </message>
    <message>
        <source>The group of held contacts</source>
        <translation>A tartósan érintkező csoport érintkezései</translation>
    </message>
    <message>
        <source>Bodies that touch (a gap of at most %1 m) and meet or part slower than the hold speed v_{hold} = %2 m/s do not bounce apart: they stay pressed together, and all the contacts of such a group are solved at once, each a row of one problem. A row&apos;s normal n points from its first ball to the other body; v_n &gt; 0 parts them.</source>
        <translation>Az egymást érintő testek (legfeljebb %1 m-es réssel), amelyek a v_{hold} = %2 m/s tartási sebességnél lassabban közelednek vagy távolodnak, nem pattannak szét: egymáshoz nyomódva maradnak, és egy ilyen csoport összes érintkezését egyszerre oldja meg a szimulátor, mindegyiket egyetlen feladat egy soraként. Egy sor n normálisa az első golyótól a másik test felé mutat; v_n &gt; 0 esetén távolodnak.</translation>
    </message>
    <message>
        <source>This group: %1 balls (%2), %3 contacts.</source>
        <translation>Ez a csoport: %1 golyó (%2), %3 érintkezés.</translation>
    </message>
    <message>
        <source>row %1 pressed</source>
        <translation>%1. sor nyomott</translation>
    </message>
    <message>
        <source>Normal impulses λ at the rows take away what relative normal speed the rows have: after them a row&apos;s speed is w = A λ + b, with b = v_n before and A the change of each row&apos;s speed per unit impulse at each row (through the balls&apos; masses: a sliding ball answers with 1/m, a rolling one with 5/7 · 1/m and keeps rolling, a ball at rest not at all; a ball in the air in 3-D). A held row ends at rest (w = 0, λ of either sign: it may draw its bodies together by at most v_{hold}); every other row only pushes: λ ≥ 0, w ≥ 0 and λ w = 0 (it presses with w = 0, or parts with λ = 0).</source>
        <translation>A sorokon ható λ normális impulzusok elveszik a sorok relatív normális sebességét: utánuk egy sor sebessége w = A λ + b, ahol b = v_n az előtti érték, A pedig az, hogy az egyes sorokon ható egységnyi impulzus mennyit változtat az egyes sorok sebességén (a golyók tömegén át: a csúszó golyó 1/m-mel válaszol, a gördülő 5/7 · 1/m-mel és tovább gördül, a nyugvó egyáltalán nem; a levegőben lévő golyó térben). A tartott sor nyugalomban végez (w = 0, λ bármilyen előjelű: legfeljebb v_{hold} sebességgel húzhatja össze testeit); minden más sor csak tol: λ ≥ 0, w ≥ 0 és λ w = 0 (nyom, ha w = 0, vagy távolodik, ha λ = 0).</translation>
    </message>
    <message>
        <source>Held this way the impulses would change a ball by more than v_{hold} per contact, so the problem was solved again with every row only pushing.</source>
        <translation>Így tartva az impulzusok egy golyót érintkezésenként több mint v_{hold}-dal változtatnának meg, ezért a feladatot újra megoldotta úgy, hogy minden sor csak tol.</translation>
    </message>
    <message>
        <source>Even pushing only, the impulses would be unsound (nearly parallel normals): they are dropped, and the balls keep their states.</source>
        <translation>Az impulzusok még csak tolva is megbízhatatlanok lennének (közel párhuzamos normálisok): elmaradnak, és a golyók megtartják állapotukat.</translation>
    </message>
    <message>
        <source>(The matrix of this many rows is not written out.)</source>
        <translation>(Ennyi sor mátrixát nem írjuk ki.)</translation>
    </message>
    <message>
        <source>Re-seating the contacts</source>
        <translation>Az érintkezések újraillesztése</translation>
    </message>
    <message>
        <source>row %1 held</source>
        <translation>%1. sor tartott</translation>
    </message>
    <message>
        <source>No row has a relative normal speed beyond rounding: no impulse is needed, λ = 0.</source>
        <translation>Egyik sornak sincs kerekítésnél nagyobb relatív normális sebessége: nincs szükség impulzusra, λ = 0.</translation>
    </message>
    <message>
        <source>Contact forces of the held segment</source>
        <translation>A tartott szakasz érintkezési erői</translation>
    </message>
    <message>
        <source>The rows kept held (%1) carry constant normal forces N ≥ 0 until the group is solved again: per row, the relative normal acceleration w = A N + b must not be negative (b: what the cloth&apos;s friction and the balls&apos; paths give without the forces), N must not be negative, and N w = 0: a row presses (w = 0) or parts (N = 0). Row k of this problem is the k-th kept row.</source>
        <translation>A tartva maradó sorok (%1) állandó N ≥ 0 normális erőt visznek, amíg a csoportot újra meg nem oldja: soronként a w = A N + b relatív normális gyorsulás nem lehet negatív (b: amit a posztó súrlódása és a golyók pályája ad az erők nélkül), N sem lehet negatív, és N w = 0: egy sor nyom (w = 0) vagy távolodik (N = 0). E feladat k-adik sora a k-adik tartva maradó sor.</translation>
    </message>
    <message>
        <source>Velocities and spins after the group&apos;s impulses</source>
        <translation>Sebességek és pörgések a csoport impulzusai után</translation>
    </message>
    <message>
        <source>Each ball&apos;s impulse J is the sum of its rows&apos; λ n (−λ n for a row&apos;s first ball); its velocity changes by c J/m (c = 1 sliding or in the air, 5/7 rolling, 0 at rest) and a rolling ball&apos;s spin follows its velocity. A slip the cloth would end within a picometre is rolled out. These are the states the simulation goes on from.</source>
        <translation>Minden golyó J impulzusa sorai λ n értékeinek összege (egy sor első golyójára −λ n); sebessége c J/m-mel változik (c = 1 csúszva vagy a levegőben, 5/7 gördülve, 0 nyugalomban), a gördülő golyó pörgése pedig követi a sebességét. Az a csúszás, amelyet a posztó egy pikométeren belül megszüntetne, kigördül. Ezekből az állapotokból folytatódik a szimuláció.</translation>
    </message>
    <message>
        <source>Re-seating the held pair</source>
        <translation>A tartott pár újraillesztése</translation>
    </message>
    <message>
        <source>The law leaves %1 (flying, f) and %2 (on the cloth, c) moving apart (or together) along n at v_n, slower than the hold speed; n points from %2&apos;s centre to %1&apos;s. An impulse J along n takes that speed away, as for any held contact: %1 takes it all (1/m_f), %2 answers with c_c of it (1 sliding, 5/7 rolling, 0 at rest: the cloth takes the rest). It only removes energy.</source>
        <translation>A törvény után %1 (repül, f) és %2 (a posztón, c) n mentén v_n sebességgel távolodik (vagy közeledik), lassabban a tartási sebességnél; n %2 középpontjától %1 középpontja felé mutat. Egy n menti J impulzus elveszi ezt a sebességet, mint minden tartott érintkezésnél: %1 egészében felveszi (1/m_f), %2 c_c részével válaszol (csúszva 1, gördülve 5/7, nyugalomban 0: a többit a posztó veszi fel). Ez csak energiát von el.</translation>
    </message>
    <message>
        <source>%1 is at rest and the push does not beat its rolling resistance (5/7 N |n_h| / m_c ≤ μ_r g): the cloth holds it still, and N carries %2&apos;s weight along n alone.</source>
        <translation>%1 nyugalomban van, és a nyomás nem győzi le a gördülési ellenállását (5/7 N |n_h| / m_c ≤ μ_r g): a posztó egy helyben tartja, és N egyedül hordozza %2 súlyát n mentén.</translation>
    </message>
    <message>
        <source>%1 is at rest and the push beats its rolling resistance: it rolls off along −n_h (c_c = 5/7), its rolling resistance μ_r g against the push.</source>
        <translation>%1 nyugalomban van, és a nyomás legyőzi a gördülési ellenállását: −n_h irányban elgördül (c_c = 5/7), μ_r g gördülési ellenállása a nyomással szemben hat.</translation>
    </message>
    <message>
        <source>%1 slides: it takes the whole push (c_c = 1), and the cloth&apos;s sliding friction μ_s g acts against its slip.</source>
        <translation>%1 csúszik: a teljes nyomást felveszi (c_c = 1), és a posztó μ_s g csúszó súrlódása a csúszásával szemben hat.</translation>
    </message>
    <message>
        <source>%1 rolls: static friction keeps it rolling (c_c = 5/7), and its rolling resistance μ_r g acts against its velocity.</source>
        <translation>%1 gördül: a tapadási súrlódás gördülésben tartja (c_c = 5/7), és μ_r g gördülési ellenállása a sebességével szemben hat.</translation>
    </message>
    <message>
        <source>The hold&apos;s contact force</source>
        <translation>A tartás érintkezési ereje</translation>
    </message>
    <message>
        <source>Here f is %1, the flying ball above, and c is %2, on the cloth.</source>
        <translation>Itt f a fent repülő %1, c pedig a posztón lévő %2.</translation>
    </message>
    <message>
        <source>From here a constant force N along n keeps the balls touching over the hold&apos;s segment: %1 flies on a parabola under gravity and N/m_f n, %2 is pushed along −n_h (the cloth takes the vertical part). N makes their relative acceleration along n part them by only a share of the curvature |v_t|²/d of their relative motion, so they never sink into each other.</source>
        <translation>Innen egy n menti állandó N erő tartja érintkezésben a golyókat a tartás szakaszán: %1 parabolán repül a gravitáció és N/m_f n hatására, %2 golyót −n_h irányban tolja (a függőleges részt a posztó veszi fel). N olyan, hogy a relatív gyorsulásuk n mentén a relatív mozgásuk |v_t|²/d görbületének csak egy részével távolítja őket, így sosem süllyednek egymásba.</translation>
    </message>
    <message>
        <source>Velocities and spins after the hold</source>
        <translation>Sebességek és pörgések a tartás után</translation>
    </message>
    <message>
        <source>The states the held pair goes on from: the re-seated velocities (the spins are the law&apos;s: the hold&apos;s impulse and force act through both centres), %1 flying and %2 on the cloth.</source>
        <translation>Az állapotok, amelyekből a tartott pár továbbhalad: az újraillesztett sebességek (a pörgések a törvényéi: a tartás impulzusa és ereje mindkét középponton át hat), %1 repül, %2 a posztón.</translation>
    </message>
</context>
</TS>
