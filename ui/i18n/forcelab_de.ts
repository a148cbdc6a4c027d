<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>BallClipboard</name>
    <message>
        <source>the clipboard holds %1 characters, more than a ball&apos;s %2</source>
        <translation>Die Zwischenablage enthält %1 Zeichen, mehr als die %2 einer Kugel</translation>
    </message>
    <message>
        <source>the clipboard does not hold a ball</source>
        <translation>Die Zwischenablage enthält keine Kugel</translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has an unknown field &quot;%1&quot;</source>
        <translation>Die Kugel in der Zwischenablage hat ein unbekanntes Feld „%1“</translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has no number &quot;%1&quot;</source>
        <translation>Die Kugel in der Zwischenablage hat keine Zahl „%1“</translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has &quot;pinned&quot; that is not true or false</source>
        <translation>Die Kugel in der Zwischenablage hat ein „pinned“, das weder true noch false ist</translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has a restitution that is not a number from 0 to 1</source>
        <translation>Die Kugel in der Zwischenablage hat eine Stoßzahl, die keine Zahl von 0 bis 1 ist</translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has no valid colour</source>
        <translation>Die Kugel in der Zwischenablage hat keine gültige Farbe</translation>
    </message>
</context>
<context>
    <name>Colour</name>
    <message>
        <source>sky blue</source>
        <translation>himmelblau</translation>
    </message>
    <message>
        <source>blue</source>
        <translation>blau</translation>
    </message>
    <message>
        <source>red</source>
        <translation>rot</translation>
    </message>
    <message>
        <source>orange</source>
        <translation>orange</translation>
    </message>
    <message>
        <source>yellow</source>
        <translation>gelb</translation>
    </message>
    <message>
        <source>green</source>
        <translation>grün</translation>
    </message>
    <message>
        <source>purple</source>
        <translation>lila</translation>
    </message>
    <message>
        <source>pink</source>
        <translation>rosa</translation>
    </message>
    <message>
        <source>black</source>
        <translation>schwarz</translation>
    </message>
    <message>
        <source>grey</source>
        <translation>grau</translation>
    </message>
    <message>
        <source>white</source>
        <translation>weiß</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <source>A workbench for forces and collisions of 2D balls.</source>
        <translation>Eine Werkbank für Kräfte und Stöße von 2D-Kugeln.</translation>
    </message>
    <message>
        <source>Lesson file or built-in lesson id.</source>
        <translation>Lektionsdatei oder Kennung einer eingebauten Lektion.</translation>
    </message>
    <message>
        <source>Save a picture of the window to FILE and quit.</source>
        <translation>Ein Bild des Fensters in FILE speichern und beenden.</translation>
    </message>
    <message>
        <source>Seconds to run in real time before --screenshot (default 3).</source>
        <translation>Sekunden Echtzeit vor --screenshot (Standard 3).</translation>
    </message>
    <message>
        <source>For --screenshot: step the lesson to simulated time T (seconds) and take the picture there, paused, instead of --after.</source>
        <translation>Für --screenshot: die Lektion bis zur simulierten Zeit T (Sekunden) rechnen und das Bild dort angehalten aufnehmen, statt --after.</translation>
    </message>
    <message>
        <source>For --screenshot: the window&apos;s size in pixels (default: the screen).</source>
        <translation>Für --screenshot: die Fenstergröße in Pixeln (Standard: der Bildschirm).</translation>
    </message>
    <message>
        <source>Open in the stage view for a projector (F11; Escape leaves).</source>
        <translation>In der Bühnenansicht für den Beamer öffnen (F11; Escape verlässt sie).</translation>
    </message>
    <message>
        <source>Time drawing 1k, 10k and 50k balls offscreen and quit.</source>
        <translation>Das Zeichnen von 1k, 10k und 50k Kugeln außerhalb des Bildschirms messen und beenden.</translation>
    </message>
    <message>
        <source>Select ball N at the start (the Inspector shows its numbers).</source>
        <translation>Kugel N beim Start auswählen (der Inspektor zeigt ihre Werte).</translation>
    </message>
    <message>
        <source>Show the table of the balls (the Balls dock, or under the box with --present), with the selected ball.</source>
        <translation>Die Tabelle der Kugeln zeigen (das Kugel-Dock, oder mit --present unter dem Kasten), mit der ausgewählten Kugel.</translation>
    </message>
    <message>
        <source>Zoom in Z times on the selected ball (or the box&apos;s middle).</source>
        <translation>Z-fach auf die ausgewählte Kugel (oder die Mitte des Kastens) zoomen.</translation>
    </message>
    <message>
        <source>Follow the selected ball (with --select).</source>
        <translation>Der ausgewählten Kugel folgen (mit --select).</translation>
    </message>
    <message>
        <source>Zoom so every ball is seen (with --time: where they are then).</source>
        <translation>So zoomen, dass jede Kugel zu sehen ist (mit --time: dort, wo sie dann sind).</translation>
    </message>
    <message>
        <source>Show the program in language CODE (en, de or es) this time, without changing the remembered one (View &gt; Language).</source>
        <translation>Das Programm diesmal in der Sprache CODE (en, de oder es) zeigen, ohne die gemerkte zu ändern (Ansicht &gt; Sprache).</translation>
    </message>
</context>
<context>
    <name>ForceModel</name>
    <message>
        <source>gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <source>drag</source>
        <translation>Luftwiderstand</translation>
    </message>
    <message>
        <source>wind</source>
        <translation>Wind</translation>
    </message>
    <message>
        <source>random</source>
        <translation>Zufall</translation>
    </message>
    <message>
        <source>point force</source>
        <translation>Punktkraft</translation>
    </message>
    <message>
        <source>pointer</source>
        <translation>Zeiger</translation>
    </message>
    <message>
        <source>spring</source>
        <translation>Feder</translation>
    </message>
    <message>
        <source>homing</source>
        <translation>Rückholkraft</translation>
    </message>
    <message>
        <source>between balls</source>
        <translation>zwischen Kugeln</translation>
    </message>
    <message>
        <source>magnetic</source>
        <translation>magnetisch</translation>
    </message>
    <message>
        <source>custom force</source>
        <translation>eigene Kraft</translation>
    </message>
</context>
<context>
    <name>Language</name>
    <message>
        <source>English</source>
        <translation>Englisch</translation>
    </message>
    <message>
        <source>German</source>
        <translation>Deutsch</translation>
    </message>
    <message>
        <source>Spanish</source>
        <translation>Spanisch</translation>
    </message>
    <message>
        <source>This lesson is not written in your language yet: its text is shown in %1.</source>
        <translation>Diese Lektion gibt es noch nicht in deiner Sprache: Ihr Text wird auf %1 gezeigt.</translation>
    </message>
</context>
<context>
    <name>Overlay</name>
    <message>
        <source>velocity</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>acceleration</source>
        <translation>Beschleunigung</translation>
    </message>
    <message>
        <source>force</source>
        <translation>Kraft</translation>
    </message>
    <message>
        <source>line of impact</source>
        <translation>Stoßlinie</translation>
    </message>
    <message>
        <source>tangent</source>
        <translation>Tangente</translation>
    </message>
    <message>
        <source>momenta  p = m v</source>
        <translation>Impulse  p = m v</translation>
    </message>
    <message>
        <source>forces by source</source>
        <translation>Kräfte nach Quelle</translation>
    </message>
</context>
<context>
    <name>Parameter</name>
    <message>
        <source>Box width</source>
        <translation>Kastenbreite</translation>
    </message>
    <message>
        <source>Box height</source>
        <translation>Kastenhöhe</translation>
    </message>
    <message>
        <source>Wall model</source>
        <translation>Wandmodell</translation>
    </message>
    <message>
        <source>Wall restitution</source>
        <translation>Stoßzahl der Wände</translation>
    </message>
    <message>
        <source>Middle wall</source>
        <translation>Mittelwand</translation>
    </message>
    <message>
        <source>Test the centre only</source>
        <translation>Nur den Mittelpunkt prüfen</translation>
    </message>
    <message>
        <source>Left wall</source>
        <translation>Linke Wand</translation>
    </message>
    <message>
        <source>Right wall</source>
        <translation>Rechte Wand</translation>
    </message>
    <message>
        <source>Top wall</source>
        <translation>Obere Wand</translation>
    </message>
    <message>
        <source>Floor</source>
        <translation>Boden</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>Step dt</source>
        <translation>Schritt dt</translation>
    </message>
    <message>
        <source>Sub-steps</source>
        <translation>Teilschritte</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <source>Move per frame</source>
        <translation>Pro Bild bewegen</translation>
    </message>
    <message>
        <source>Step past close passes</source>
        <translation>Über nahe Vorbeiflüge hinweg</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <source>g x (right)</source>
        <translation>g x (rechts)</translation>
    </message>
    <message>
        <source>g y (down)</source>
        <translation>g y (unten)</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Luftwiderstand</translation>
    </message>
    <message>
        <source>Drag law</source>
        <translation>Widerstandsgesetz</translation>
    </message>
    <message>
        <source>Drag k</source>
        <translation>Widerstand k</translation>
    </message>
    <message>
        <source>Drag scaling</source>
        <translation>Widerstand skaliert mit</translation>
    </message>
    <message>
        <source>Wind</source>
        <translation>Wind</translation>
    </message>
    <message>
        <source>Wind strength</source>
        <translation>Windstärke</translation>
    </message>
    <message>
        <source>Wind scaling</source>
        <translation>Wind skaliert mit</translation>
    </message>
    <message>
        <source>Smoothed step</source>
        <translation>Glättungsschritt</translation>
    </message>
    <message>
        <source>Noise frequency</source>
        <translation>Rauschfrequenz</translation>
    </message>
    <message>
        <source>Compare with</source>
        <translation>Vergleichen mit</translation>
    </message>
    <message>
        <source>Random acceleration</source>
        <translation>Zufällige Beschleunigung</translation>
    </message>
    <message>
        <source>One value per ball</source>
        <translation>Ein Wert pro Kugel</translation>
    </message>
    <message>
        <source>Random strength</source>
        <translation>Zufallsstärke</translation>
    </message>
    <message>
        <source>Un-centred (0 to strength)</source>
        <translation>Nicht zentriert (0 bis Stärke)</translation>
    </message>
    <message>
        <source>Point force</source>
        <translation>Punktkraft</translation>
    </message>
    <message>
        <source>Point kind</source>
        <translation>Art des Punkts</translation>
    </message>
    <message>
        <source>Point x</source>
        <translation>Punkt x</translation>
    </message>
    <message>
        <source>Point y</source>
        <translation>Punkt y</translation>
    </message>
    <message>
        <source>Point strength</source>
        <translation>Punktstärke</translation>
    </message>
    <message>
        <source>Point clamp (0 = off)</source>
        <translation>Punkt-Obergrenze (0 = aus)</translation>
    </message>
    <message>
        <source>Point scaling</source>
        <translation>Punkt skaliert mit</translation>
    </message>
    <message>
        <source>Un-normalised (S d / d²)</source>
        <translation>Nicht normiert (S d / d²)</translation>
    </message>
    <message>
        <source>Spring</source>
        <translation>Feder</translation>
    </message>
    <message>
        <source>Anchor x</source>
        <translation>Ankerpunkt x</translation>
    </message>
    <message>
        <source>Anchor y</source>
        <translation>Ankerpunkt y</translation>
    </message>
    <message>
        <source>Spring k</source>
        <translation>Feder k</translation>
    </message>
    <message>
        <source>Gravity between balls</source>
        <translation>Schwerkraft zwischen Kugeln</translation>
    </message>
    <message>
        <source>G</source>
        <translation>G</translation>
    </message>
    <message>
        <source>Softening ε</source>
        <translation>Glättung ε</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Rückholkraft</translation>
    </message>
    <message>
        <source>Homing strength</source>
        <translation>Stärke der Rückholkraft</translation>
    </message>
    <message>
        <source>Pointer force</source>
        <translation>Mauszeiger-Kraft</translation>
    </message>
    <message>
        <source>Pointer strength</source>
        <translation>Stärke des Mauszeigers</translation>
    </message>
    <message>
        <source>Pointer clamp (0 = off)</source>
        <translation>Mauszeiger-Obergrenze (0 = aus)</translation>
    </message>
    <message>
        <source>Magnetic field</source>
        <translation>Magnetfeld</translation>
    </message>
    <message>
        <source>Field B</source>
        <translation>Feld B</translation>
    </message>
    <message>
        <source>Custom force</source>
        <translation>Eigene Kraft</translation>
    </message>
    <message>
        <source>Formulas give a, not F</source>
        <translation>Formeln geben a, nicht F</translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation>Tempolimit</translation>
    </message>
    <message>
        <source>Largest speed</source>
        <translation>Höchstes Tempo</translation>
    </message>
    <message>
        <source>Detection</source>
        <translation>Erkennung</translation>
    </message>
    <message>
        <source>Response</source>
        <translation>Antwort</translation>
    </message>
    <message>
        <source>Ball restitution</source>
        <translation>Stoßzahl der Kugeln</translation>
    </message>
    <message>
        <source>Continuous</source>
        <translation>Kontinuierlich</translation>
    </message>
    <message>
        <source>Resting contacts</source>
        <translation>Ruhende Kontakte</translation>
    </message>
</context>
<context>
    <name>ParameterHelp</name>
    <message>
        <source>Width of the box the balls live in.</source>
        <translation>Breite des Kastens, in dem die Kugeln leben.</translation>
    </message>
    <message>
        <source>Height of the box; y points down.</source>
        <translation>Höhe des Kastens; y zeigt nach unten.</translation>
    </message>
    <message>
        <source>How a ball that crossed a wall is put back: clamp, mirror, exact (time of impact) or reverse.</source>
        <translation>Wie eine Kugel, die eine Wand überquert hat, zurückgesetzt wird: clamp, mirror, exact (Zeitpunkt des Aufpralls) oder reverse.</translation>
    </message>
    <message>
        <source>Share of the speed into a wall that a bounce keeps: 1 loses nothing, 0 stops the ball.</source>
        <translation>Anteil des Tempos auf eine Wand zu, den ein Abprall behält: 1 verliert nichts, 0 stoppt die Kugel.</translation>
    </message>
    <message>
        <source>A wall down the middle of the box; each ball stays on its side.</source>
        <translation>Eine Wand in der Mitte des Kastens; jede Kugel bleibt auf ihrer Seite.</translation>
    </message>
    <message>
        <source>The wall test uses the ball&apos;s centre instead of its edge (stage 3&apos;s bug).</source>
        <translation>Der Wandtest nimmt den Mittelpunkt der Kugel statt ihres Rands (der Fehler aus Stufe 3).</translation>
    </message>
    <message>
        <source>A wall at x = 0 (in lesson files: &quot;left&quot; in the walls list).</source>
        <translation>Eine Wand bei x = 0 (in Lektionsdateien: &quot;left&quot; in der Liste walls).</translation>
    </message>
    <message>
        <source>A wall at x = width.</source>
        <translation>Eine Wand bei x = Breite.</translation>
    </message>
    <message>
        <source>A wall at y = 0.</source>
        <translation>Eine Wand bei y = 0.</translation>
    </message>
    <message>
        <source>A wall at y = height.</source>
        <translation>Eine Wand bei y = Höhe.</translation>
    </message>
    <message>
        <source>The method that moves the balls through one step.</source>
        <translation>Das Verfahren, das die Kugeln einen Schritt weiterbewegt.</translation>
    </message>
    <message>
        <source>Simulated time of one step.</source>
        <translation>Simulierte Zeit eines Schritts.</translation>
    </message>
    <message>
        <source>Each step is split into this many equal sub-steps.</source>
        <translation>Jeder Schritt wird in so viele gleiche Teilschritte geteilt.</translation>
    </message>
    <message>
        <source>Error allowed per sub-step by the adaptive integrators (rk45, ias15); ias15 works to the rounding floor where this asks for less.</source>
        <translation>Erlaubter Fehler pro Teilschritt für die adaptiven Integratoren (rk45, ias15); ias15 rechnet bis an die Rundungsgrenze, wo hier weniger verlangt wird.</translation>
    </message>
    <message>
        <source>Ignore dt: every step moves the balls as if 1/60 s had passed (stage 5&apos;s bug).</source>
        <translation>dt nicht beachten: jeder Schritt bewegt die Kugeln, als wären 1/60 s vergangen (der Fehler aus Stufe 5).</translation>
    </message>
    <message>
        <source>Let a fixed step jump past a close pass it cannot follow instead of stopping there (stage 17&apos;s slingshot bug).</source>
        <translation>Einen festen Schritt über einen nahen Vorbeiflug springen lassen, dem er nicht folgen kann, statt dort anzuhalten (der Schleuder-Fehler aus Stufe 17).</translation>
    </message>
    <message>
        <source>The same downward pull on every ball.</source>
        <translation>Derselbe Zug nach unten auf jede Kugel.</translation>
    </message>
    <message>
        <source>Sideways part of gravity.</source>
        <translation>Seitlicher Anteil der Schwerkraft.</translation>
    </message>
    <message>
        <source>Downward part of gravity; 980 px/s² is Earth&apos;s if 1 px is 1 cm.</source>
        <translation>Anteil der Schwerkraft nach unten; 980 px/s² ist die der Erde, wenn 1 px 1 cm ist.</translation>
    </message>
    <message>
        <source>A force against the velocity.</source>
        <translation>Eine Kraft gegen die Geschwindigkeit.</translation>
    </message>
    <message>
        <source>linear: F ∝ −v; quadratic: F ∝ −|v| v.</source>
        <translation>linear: F ∝ −v; quadratic: F ∝ −|v| v.</translation>
    </message>
    <message>
        <source>How strong the drag is: how fast a 10 px ball slows down.</source>
        <translation>Wie stark der Luftwiderstand ist: wie schnell eine 10-px-Kugel langsamer wird.</translation>
    </message>
    <message>
        <source>mass: drag is a force, F = −k m(10 px) v, so a heavy ball slows down less and falls faster; none: the tutorial&apos;s model, every ball loses the same share of its speed; radius: air drag on spheres, × 10 px / r.</source>
        <translation>mass: der Widerstand ist eine Kraft, F = −k m(10 px) v, also wird eine schwere Kugel weniger gebremst und fällt schneller; none: das Modell des Kurses, jede Kugel verliert denselben Anteil ihres Tempos; radius: Luftwiderstand von Kugeln, × 10 px / r.</translation>
    </message>
    <message>
        <source>off, random (a new gust every step), smoothed (a bounded random walk), noise (smooth noise) or pointer (blown by the mouse).</source>
        <translation>off, random (jeden Schritt eine neue Böe), smoothed (eine begrenzte Irrfahrt), noise (glattes Rauschen) oder pointer (von der Maus geblasen).</translation>
    </message>
    <message>
        <source>Largest sideways push on a 10 px ball.</source>
        <translation>Größter seitlicher Stoß auf eine 10-px-Kugel.</translation>
    </message>
    <message>
        <source>none: every ball is pushed alike; radius: by 10 px / r; mass: as a force, by m(10 px) / m.</source>
        <translation>none: jede Kugel wird gleich geschoben; radius: mit 10 px / r; mass: als Kraft, mit m(10 px) / m.</translation>
    </message>
    <message>
        <source>Largest change of the smoothed wind per step, as a share of its strength.</source>
        <translation>Größte Änderung des geglätteten Winds pro Schritt, als Anteil seiner Stärke.</translation>
    </message>
    <message>
        <source>How fast the noise wind changes.</source>
        <translation>Wie schnell sich der Rauschwind ändert.</translation>
    </message>
    <message>
        <source>A second wind computed beside the first for a second vane; it pushes nothing.</source>
        <translation>Ein zweiter Wind, neben dem ersten berechnet, für ein zweites Windrad; er schiebt nichts.</translation>
    </message>
    <message>
        <source>A random push on every ball, centred on zero (stage 10).</source>
        <translation>Ein zufälliger Stoß auf jede Kugel, um null zentriert (Stufe 10).</translation>
    </message>
    <message>
        <source>Off: a new random value every step. On: each ball keeps the value it drew first.</source>
        <translation>Aus: jeden Schritt ein neuer Zufallswert. An: jede Kugel behält den Wert, den sie zuerst gezogen hat.</translation>
    </message>
    <message>
        <source>Largest value of each component.</source>
        <translation>Größter Wert jeder Komponente.</translation>
    </message>
    <message>
        <source>The course&apos;s Math.random() bug: each component is drawn in [0, strength) instead of [−strength, strength), so every ball drifts right and down at strength/2 on average.</source>
        <translation>Der Math.random()-Fehler des Kurses: jede Komponente wird aus [0, Stärke) statt aus [−Stärke, Stärke) gezogen, also treibt jede Kugel im Mittel mit Stärke/2 nach rechts und unten.</translation>
    </message>
    <message>
        <source>An inverse-square pull or push from a fixed point.</source>
        <translation>Ein Zug oder Schub von einem festen Punkt, umgekehrt proportional zum Quadrat des Abstands.</translation>
    </message>
    <message>
        <source>attract or repel.</source>
        <translation>attract oder repel.</translation>
    </message>
    <message>
        <source>Where the point is, across.</source>
        <translation>Wo der Punkt ist, waagerecht.</translation>
    </message>
    <message>
        <source>Where the point is, down.</source>
        <translation>Wo der Punkt ist, senkrecht.</translation>
    </message>
    <message>
        <source>S in a = S / d² for a 10 px ball.</source>
        <translation>S in a = S / d² für eine 10-px-Kugel.</translation>
    </message>
    <message>
        <source>The point&apos;s pull is never more than this near it.</source>
        <translation>Der Zug des Punkts ist in seiner Nähe nie größer als dieser Wert.</translation>
    </message>
    <message>
        <source>none, radius or mass, as for the wind.</source>
        <translation>none, radius oder mass, wie beim Wind.</translation>
    </message>
    <message>
        <source>The course&apos;s repulsion bug: the difference vector d times S / d² instead of its unit vector, so |a| = S / d, a 1/d law, not S / d².</source>
        <translation>Der Abstoßungs-Fehler des Kurses: der Abstandsvektor d mal S / d² statt seines Einheitsvektors, also |a| = S / d, ein 1/d-Gesetz statt S / d².</translation>
    </message>
    <message>
        <source>Every ball tied to one anchor by a spring (Hooke&apos;s law).</source>
        <translation>Jede Kugel hängt an einer Feder an einem Anker (hookesches Gesetz).</translation>
    </message>
    <message>
        <source>Where the springs are tied, across.</source>
        <translation>Wo die Federn befestigt sind, waagerecht.</translation>
    </message>
    <message>
        <source>Where the springs are tied, down.</source>
        <translation>Wo die Federn befestigt sind, senkrecht.</translation>
    </message>
    <message>
        <source>Stiffness per unit mass: a = −k (x − anchor), so ω = √k.</source>
        <translation>Steifigkeit pro Masseneinheit: a = −k (x − Anker), also ω = √k.</translation>
    </message>
    <message>
        <source>Every pair of balls pulls together (or pushes apart for G &lt; 0).</source>
        <translation>Jedes Paar von Kugeln zieht sich an (oder stößt sich ab für G &lt; 0).</translation>
    </message>
    <message>
        <source>The constant in F = G m₁ m₂ / r².</source>
        <translation>Die Konstante in F = G m₁ m₂ / r².</translation>
    </message>
    <message>
        <source>ε in F = G m₁ m₂ r / (r² + ε²)^(3/2): the pull fades smoothly to zero inside ε.</source>
        <translation>ε in F = G m₁ m₂ r / (r² + ε²)^(3/2): innerhalb von ε geht der Zug glatt auf null zurück.</translation>
    </message>
    <message>
        <source>Each ball tied by a spring to the home of its colour.</source>
        <translation>Jede Kugel hängt an einer Feder am Zuhause ihrer Farbe.</translation>
    </message>
    <message>
        <source>Stiffness of the spring to home, per unit mass.</source>
        <translation>Steifigkeit der Feder nach Hause, pro Masseneinheit.</translation>
    </message>
    <message>
        <source>The mouse pointer pulls (hover) or pushes (pressed).</source>
        <translation>Der Mauszeiger zieht (beim Darüberfahren) oder schiebt (gedrückt).</translation>
    </message>
    <message>
        <source>S in a = S / d².</source>
        <translation>S in a = S / d².</translation>
    </message>
    <message>
        <source>The pointer&apos;s pull is never more than this.</source>
        <translation>Der Zug des Zeigers ist nie größer als dieser Wert.</translation>
    </message>
    <message>
        <source>A field out of the screen that turns every moving charge, F = q v × B, without changing its speed.</source>
        <translation>Ein Feld aus dem Bildschirm heraus, das jede bewegte Ladung ablenkt, F = q v × B, ohne ihr Tempo zu ändern.</translation>
    </message>
    <message>
        <source>How fast a 10 px ball of charge 1 turns: ω = q B m(10 px) / m; negative turns the other way.</source>
        <translation>Wie schnell sich eine 10-px-Kugel mit Ladung 1 dreht: ω = q B m(10 px) / m; negativ dreht andersherum.</translation>
    </message>
    <message>
        <source>A force law written as formulas of x, y, vx, vy, m, r, q, t, W, H and named constants (the Force editor).</source>
        <translation>Ein Kraftgesetz als Formeln von x, y, vx, vy, m, r, q, t, W, H und benannten Konstanten (der Kraft-Editor).</translation>
    </message>
    <message>
        <source>On: the formulas are the acceleration (px/s²), the same for every mass; off: the force, divided by m.</source>
        <translation>An: die Formeln sind die Beschleunigung (px/s²), für jede Masse gleich; aus: die Kraft, geteilt durch m.</translation>
    </message>
    <message>
        <source>No ball moves faster than the limit (a stand-in for terminal velocity).</source>
        <translation>Keine Kugel bewegt sich schneller als die Grenze (ein Ersatz für die Endgeschwindigkeit).</translation>
    </message>
    <message>
        <source>The limit.</source>
        <translation>Die Grenze.</translation>
    </message>
    <message>
        <source>How touching pairs are found: brute, halved, sweep or grid.</source>
        <translation>Wie sich berührende Paare gefunden werden: brute, halved, sweep oder grid.</translation>
    </message>
    <message>
        <source>What a touching pair does: none, flag, 1d-reverse, 1d-elastic, 2d-axis or 2d-impulse.</source>
        <translation>Was ein sich berührendes Paar tut: none, flag, 1d-reverse, 1d-elastic, 2d-axis oder 2d-impulse.</translation>
    </message>
    <message>
        <source>Share of the approach speed a collision gives back.</source>
        <translation>Anteil der Annäherungsgeschwindigkeit, den ein Stoß zurückgibt.</translation>
    </message>
    <message>
        <source>Find the moment of impact inside the step.</source>
        <translation>Den Zeitpunkt des Aufpralls innerhalb des Schritts finden.</translation>
    </message>
    <message>
        <source>Under gravity, solve a pile&apos;s contacts several times per step so it stands.</source>
        <translation>Unter Schwerkraft die Kontakte eines Stapels mehrmals pro Schritt lösen, damit er steht.</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Change speed to %1×</source>
        <translation>Tempo auf %1× ändern</translation>
    </message>
    <message>
        <source>Walls: is the ball outside the box?</source>
        <translation>Wände: Ist die Kugel außerhalb des Kastens?</translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation>Tempolimit</translation>
    </message>
    <message>
        <source>Rule %1</source>
        <translation>Regel %1</translation>
    </message>
    <message>
        <source>Goal:</source>
        <translation>Ziel:</translation>
    </message>
    <message>
        <source>about %1 minutes</source>
        <translation>etwa %1 Minuten</translation>
    </message>
    <message>
        <source>Expected answers</source>
        <translation>Erwartete Antworten</translation>
    </message>
    <message>
        <source>Common misconceptions</source>
        <translation>Häufige Fehlvorstellungen</translation>
    </message>
    <message>
        <source>What the scene is checked to show</source>
        <translation>Was die Szene nachweislich zeigt</translation>
    </message>
    <message>
        <source>ForceLab: teacher&apos;s handbook</source>
        <translation>ForceLab: Handbuch für Lehrkräfte</translation>
    </message>
    <message>
        <source>One section per lesson: the goal, the time it takes, the text students read, the challenges with their expected answers, the misconceptions to expect, and what the scene is checked to show (forcelab-cli check).</source>
        <translation>Ein Abschnitt pro Lektion: das Ziel, die benötigte Zeit, der Text für die Schülerinnen und Schüler, die Aufgaben mit den erwarteten Antworten, die zu erwartenden Fehlvorstellungen und was die Szene nachweislich zeigt (forcelab-cli check).</translation>
    </message>
    <message>
        <source>Showcase</source>
        <translation>Vorführung</translation>
    </message>
    <message>
        <source>Stage %1 of 29</source>
        <translation>Stufe %1 von 29</translation>
    </message>
    <message>
        <source>Beyond the course</source>
        <translation>Über den Kurs hinaus</translation>
    </message>
    <message>
        <source>Challenges</source>
        <translation>Aufgaben</translation>
    </message>
    <message>
        <source>For the teacher</source>
        <translation>Für die Lehrkraft</translation>
    </message>
</context>
<context>
    <name>SceneDescription</name>
    <message>
        <source>right</source>
        <translation>nach rechts</translation>
    </message>
    <message>
        <source>up and to the right</source>
        <translation>nach rechts oben</translation>
    </message>
    <message>
        <source>up</source>
        <translation>nach oben</translation>
    </message>
    <message>
        <source>up and to the left</source>
        <translation>nach links oben</translation>
    </message>
    <message>
        <source>left</source>
        <translation>nach links</translation>
    </message>
    <message>
        <source>down and to the left</source>
        <translation>nach links unten</translation>
    </message>
    <message>
        <source>down</source>
        <translation>nach unten</translation>
    </message>
    <message>
        <source>down and to the right</source>
        <translation>nach rechts unten</translation>
    </message>
    <message>
        <source>the left wall</source>
        <translation>die linke Wand</translation>
    </message>
    <message>
        <source>the right wall</source>
        <translation>die rechte Wand</translation>
    </message>
    <message>
        <source>the ceiling</source>
        <translation>die Decke</translation>
    </message>
    <message>
        <source>the floor</source>
        <translation>den Boden</translation>
    </message>
    <message>
        <source>the middle wall</source>
        <translation>die Mittelwand</translation>
    </message>
    <message>
        <source>No balls.</source>
        <translation>Keine Kugeln.</translation>
    </message>
    <message>
        <source>One ball.</source>
        <translation>Eine Kugel.</translation>
    </message>
    <message>
        <source>%1 balls.</source>
        <translation>%1 Kugeln.</translation>
    </message>
    <message>
        <source>Ball %1</source>
        <translation>Kugel %1</translation>
    </message>
    <message>
        <source>Ball %1 (%2)</source>
        <translation>Kugel %1 (%2)</translation>
    </message>
    <message>
        <source>%1 is pinned in place.</source>
        <translation>%1 ist festgeheftet.</translation>
    </message>
    <message>
        <source>%1 is at rest.</source>
        <translation>%1 ruht.</translation>
    </message>
    <message>
        <source>%1 moves %2 at %3</source>
        <translation>%1 bewegt sich %2 mit %3</translation>
    </message>
    <message>
        <source>will hit %1 in %2 s</source>
        <translation>trifft in %2 s auf %1</translation>
    </message>
    <message>
        <source>will hit %1 in about %2 s</source>
        <translation>trifft in etwa %2 s auf %1</translation>
    </message>
    <message>
        <source>and %1.</source>
        <translation>und %1.</translation>
    </message>
    <message>
        <source>It %1.</source>
        <translation>Sie %1.</translation>
    </message>
    <message>
        <source>Total energy %1.</source>
        <translation>Gesamtenergie %1.</translation>
    </message>
</context>
<context>
    <name>WorldPainter</name>
    <message>
        <source>ball %1</source>
        <translation>Kugel %1</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>Tempo</translation>
    </message>
    <message>
        <source>position</source>
        <translation>Ort</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>Geschw.</translation>
    </message>
    <message>
        <source>accel.</source>
        <translation>Beschl.</translation>
    </message>
    <message>
        <source>kinetic</source>
        <translation>kinetisch</translation>
    </message>
    <message>
        <source>potential</source>
        <translation>potenziell</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>energy in %1: %2 %3</source>
        <translation>Energie in %1: %2 %3</translation>
    </message>
    <message>
        <source>momentum (%1, %2) %3</source>
        <translation>Impuls (%1, %2) %3</translation>
    </message>
    <message>
        <source>energy in %1</source>
        <translation>Energie in %1</translation>
    </message>
    <message>
        <source>momentum in %1</source>
        <translation>Impuls in %1</translation>
    </message>
    <message>
        <source>energy (%1)</source>
        <translation>Energie (%1)</translation>
    </message>
    <message>
        <source>momentum (%1)</source>
        <translation>Impuls (%1)</translation>
    </message>
</context>
<context>
    <name>forcelab::AccuracyDock</name>
    <message>
        <source>Accuracy</source>
        <translation>Genauigkeit</translation>
    </message>
    <message>
        <source>Drift</source>
        <translation>Drift</translation>
    </message>
    <message>
        <source>Ghost</source>
        <translation>Geist</translation>
    </message>
    <message>
        <source>Trade-off</source>
        <translation>Abwägung</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Aus</translation>
    </message>
    <message>
        <source>Compare with another integrator</source>
        <translation>Mit einem anderen Integrator vergleichen</translation>
    </message>
    <message>
        <source>Sensitivity twin (moved 1e-10 px)</source>
        <translation>Empfindlichkeits-Zwilling (um 1e-10 px verschoben)</translation>
    </message>
    <message>
        <source>dt (same)</source>
        <translation>dt (gleich)</translation>
    </message>
    <message>
        <source>dt / %1</source>
        <translation>dt / %1</translation>
    </message>
    <message>
        <source>Draw the ghost on the canvas</source>
        <translation>Den Geist auf der Zeichenfläche zeigen</translation>
    </message>
    <message>
        <source>Ghost:</source>
        <translation>Geist:</translation>
    </message>
    <message>
        <source>Its integrator:</source>
        <translation>Sein Integrator:</translation>
    </message>
    <message>
        <source>Its step:</source>
        <translation>Sein Schritt:</translation>
    </message>
    <message>
        <source>Separation:</source>
        <translation>Abstand:</translation>
    </message>
    <message>
        <source>t, s</source>
        <translation>t, s</translation>
    </message>
    <message>
        <source>px</source>
        <translation>px</translation>
    </message>
    <message>
        <source>Measure the &amp;Trade-off</source>
        <translation>&amp;Abwägung messen</translation>
    </message>
    <message>
        <source>Run the current scene with every integrator at several steps and plot error against cost</source>
        <translation>Die aktuelle Szene mit jedem Integrator bei mehreren Schrittweiten laufen lassen und den Fehler gegen den Aufwand auftragen</translation>
    </message>
    <message>
        <source>Check &amp;Convergence</source>
        <translation>&amp;Konvergenz prüfen</translation>
    </message>
    <message>
        <source>Rerun the current scene at dt, dt/2, dt/4, dt/8 and fit the order</source>
        <translation>Die aktuelle Szene mit dt, dt/2, dt/4, dt/8 erneut laufen lassen und die Ordnung anpassen</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Runs the lesson&apos;s scene for %1 s with each integrator.</source>
        <translation>Lässt die Szene der Lektion %1 s lang mit jedem Integrator laufen.</translation>
    </message>
    <message>
        <source>Error against cost, both on log scales: lower left is better</source>
        <translation>Fehler gegen Aufwand, beide logarithmisch: unten links ist besser</translation>
    </message>
    <message>
        <source>(E now − E at the start − energy added or removed on purpose) / |E at the start|: the integrator&apos;s own error</source>
        <translation>(E jetzt − E am Anfang − absichtlich zugeführte oder entzogene Energie) / |E am Anfang|: der eigene Fehler des Integrators</translation>
    </message>
    <message>
        <source>Energy added (+) or removed (−) on purpose by drag, wind, walls, collisions, the pointer and edits, relative to |E at the start|</source>
        <translation>Energie, die absichtlich durch Luftwiderstand, Wind, Wände, Stöße, den Mauszeiger und Änderungen zugeführt (+) oder entzogen (−) wurde, relativ zu |E am Anfang|</translation>
    </message>
    <message>
        <source>|p now − p at the start − impulse of the outside forces|</source>
        <translation>|p jetzt − p am Anfang − Kraftstoß der äußeren Kräfte|</translation>
    </message>
    <message>
        <source>Energy drift ΔE/|E₀|:</source>
        <translation>Energiedrift ΔE/|E₀|:</translation>
    </message>
    <message>
        <source>Booked on purpose /|E₀|:</source>
        <translation>Absichtlich verbucht /|E₀|:</translation>
    </message>
    <message>
        <source>Momentum drift |Δp|:</source>
        <translation>Impulsdrift |Δp|:</translation>
    </message>
    <message>
        <source>Force evaluations per simulated s:</source>
        <translation>Kraftberechnungen pro simulierter s:</translation>
    </message>
    <message>
        <source>Step cost:</source>
        <translation>Aufwand pro Schritt:</translation>
    </message>
    <message>
        <source>Energy added or taken away on purpose (drag, wind, walls, collisions, your pointer, edits) is booked apart. What is left should be zero: it is the integrator&apos;s own error.</source>
        <translation>Energie, die absichtlich zugeführt oder entzogen wird (Luftwiderstand, Wind, Wände, Stöße, dein Mauszeiger, Änderungen), wird getrennt verbucht. Was übrig bleibt, sollte null sein: Es ist der eigene Fehler des Integrators.</translation>
    </message>
    <message>
        <source>Start Counting Again</source>
        <translation>Neu zählen</translation>
    </message>
    <message>
        <source>%1 ms, %2</source>
        <translation>%1 ms, %2</translation>
    </message>
    <message>
        <source>force evaluation</source>
        <translation>Kraftberechnung</translation>
    </message>
    <message>
        <source>force evaluations</source>
        <translation>Kraftberechnungen</translation>
    </message>
    <message>
        <source>Measuring %1 runs of %2 s…</source>
        <translation>Messe %1 Läufe zu je %2 s …</translation>
    </message>
    <message>
        <source>Running %1 at dt, dt/2, dt/4, dt/8 for %2 s…</source>
        <translation>%1 läuft mit dt, dt/2, dt/4, dt/8 für %2 s …</translation>
    </message>
    <message>
        <source>Could not measure: %1</source>
        <translation>Messung nicht möglich: %1</translation>
    </message>
    <message>
        <source>Cancelled after %1 runs.</source>
        <translation>Nach %1 Läufen abgebrochen.</translation>
    </message>
    <message>
        <source>Done: %1 runs against ias15 at dt/8. Each dot is one run; a steeper line is a higher order. Fitted orders: %2.</source>
        <translation>Fertig: %1 Läufe gegen ias15 bei dt/8. Jeder Punkt ist ein Lauf; eine steilere Linie bedeutet eine höhere Ordnung. Angepasste Ordnungen: %2.</translation>
    </message>
    <message>
        <source>%1 cannot run this scene: %2</source>
        <translation>%1 kann diese Szene nicht ausführen: %2</translation>
    </message>
    <message>
        <source>dt = %1 s: error %2</source>
        <translation>dt = %1 s: Fehler %2</translation>
    </message>
    <message>
        <source>%1: fitted order %2</source>
        <translation>%1: angepasste Ordnung %2</translation>
    </message>
    <message>
        <source> (theory: %1)</source>
        <translation> (Theorie: %1)</translation>
    </message>
    <message>
        <source>cost: force evaluations</source>
        <translation>Aufwand: Kraftberechnungen</translation>
    </message>
    <message>
        <source>error, px</source>
        <translation>Fehler, px</translation>
    </message>
</context>
<context>
    <name>forcelab::ArrowLegendView</name>
    <message>
        <source>An arrow this long stands for %1</source>
        <translation>Ein so langer Pfeil steht für %1</translation>
    </message>
</context>
<context>
    <name>forcelab::BallTable</name>
    <message>
        <source>Balls</source>
        <translation>Kugeln</translation>
    </message>
    <message>
        <source>Double-click a number to type a new one. Undo (Ctrl+Z) takes it back.</source>
        <translation>Doppelklicke auf eine Zahl, um eine neue einzugeben. Rückgängig (Ctrl+Z) nimmt es zurück.</translation>
    </message>
    <message>
        <source>⚠ %1</source>
        <translation>⚠ %1</translation>
    </message>
</context>
<context>
    <name>forcelab::BallTableModel</name>
    <message>
        <source>world</source>
        <translation>Welt</translation>
    </message>
    <message>
        <source>Radius. A new radius keeps the density: twice as big is 8 times the mass.</source>
        <translation>Radius. Ein neuer Radius behält die Dichte bei: doppelt so groß heißt 8-fache Masse.</translation>
    </message>
    <message>
        <source>Mass, in the mass units of the lesson (a 10 px ball of density 1 has 4189). Independent of the size: a small ball can be heavy.</source>
        <translation>Masse, in den Masseneinheiten der Lektion (eine 10-px-Kugel mit Dichte 1 hat 4189). Unabhängig von der Größe: Eine kleine Kugel kann schwer sein.</translation>
    </message>
    <message>
        <source>Mass per volume of a sphere: 1 is the density of every ball a lesson does not give a mass.</source>
        <translation>Masse pro Volumen einer Kugel: 1 ist die Dichte jeder Kugel, der eine Lektion keine Masse gibt.</translation>
    </message>
    <message>
        <source>What a magnetic field acts on (1: like the 10 px reference ball).</source>
        <translation>Worauf ein Magnetfeld wirkt (1: wie die 10-px-Referenzkugel).</translation>
    </message>
    <message>
        <source>How much of its speed this ball keeps in a bounce: 0 stops it dead, 1 keeps it all. &quot;world&quot;: the scene&apos;s value. When two balls hit, the smaller value counts. Clear the cell to go back to the world&apos;s.</source>
        <translation>Wie viel ihres Tempos diese Kugel beim Aufprall behält: 0 stoppt sie ganz, 1 behält alles. „Welt“: der Wert der Szene. Stoßen zwei Kugeln zusammen, zählt der kleinere Wert. Leere die Zelle, um zum Wert der Welt zurückzukehren.</translation>
    </message>
    <message>
        <source>A pinned ball never moves: other balls bounce off it as off a ball too heavy to push.</source>
        <translation>Eine festgehaltene Kugel bewegt sich nie: Andere Kugeln prallen von ihr ab wie von einer Kugel, die zu schwer zum Schieben ist.</translation>
    </message>
    <message>
        <source>Ball</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <source>x (%1)</source>
        <translation>x (%1)</translation>
    </message>
    <message>
        <source>y (%1)</source>
        <translation>y (%1)</translation>
    </message>
    <message>
        <source>vx (%1)</source>
        <translation>vx (%1)</translation>
    </message>
    <message>
        <source>vy (%1)</source>
        <translation>vy (%1)</translation>
    </message>
    <message>
        <source>r (%1)</source>
        <translation>r (%1)</translation>
    </message>
    <message>
        <source>mass (%1)</source>
        <translation>Masse (%1)</translation>
    </message>
    <message>
        <source>mass</source>
        <translation>Masse</translation>
    </message>
    <message>
        <source>density</source>
        <translation>Dichte</translation>
    </message>
    <message>
        <source>charge</source>
        <translation>Ladung</translation>
    </message>
    <message>
        <source>colour</source>
        <translation>Farbe</translation>
    </message>
    <message>
        <source>restitution</source>
        <translation>Stoßzahl</translation>
    </message>
    <message>
        <source>pinned</source>
        <translation>fest</translation>
    </message>
    <message>
        <source>Pin ball %1</source>
        <translation>Kugel %1 festhalten</translation>
    </message>
    <message>
        <source>Free ball %1</source>
        <translation>Kugel %1 freigeben</translation>
    </message>
    <message>
        <source>Give ball %1 the world&apos;s restitution</source>
        <translation>Kugel %1 die Stoßzahl der Welt geben</translation>
    </message>
    <message>
        <source>colour: &quot;%1&quot; is not a colour; type a name like red or #e05050</source>
        <translation>Farbe: „%1“ ist keine Farbe; gib einen Namen wie red oder #e05050 ein</translation>
    </message>
    <message>
        <source>Colour of ball %1</source>
        <translation>Farbe von Kugel %1</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1: „%2“ ist keine Zahl</translation>
    </message>
    <message>
        <source>Set %1 of ball %2</source>
        <translation>%1 von Kugel %2 setzen</translation>
    </message>
    <message>
        <source>restitution: %1 is outside %2; leave it empty for the world&apos;s</source>
        <translation>Stoßzahl: %1 liegt außerhalb von %2; lass das Feld leer für den Wert der Welt</translation>
    </message>
</context>
<context>
    <name>forcelab::Canvas</name>
    <message>
        <source>Simulation stage</source>
        <translation>Simulationsbühne</translation>
    </message>
    <message>
        <source>%1 at %2°</source>
        <translation>%1 unter %2°</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>reference (the course&apos;s code) · energy %1</source>
        <translation>Referenz (Code des Kurses) · Energie %1</translation>
    </message>
    <message>
        <source>your code stopped: %1</source>
        <translation>dein Code wurde angehalten: %1</translation>
    </message>
    <message>
        <source>your code departs at step %1: %2 balls, the reference has %3</source>
        <translation>dein Code weicht ab bei Schritt %1: %2 Kugeln, die Referenz hat %3</translation>
    </message>
    <message>
        <source>your code departs at step %1 (ball %2, %3 off by %4) · energy %5</source>
        <translation>dein Code weicht ab bei Schritt %1 (Kugel %2, %3 um %4 daneben) · Energie %5</translation>
    </message>
    <message>
        <source>your code · agrees for %1 steps · energy %2</source>
        <translation>dein Code · stimmt seit %1 Schritten überein · Energie %2</translation>
    </message>
    <message>
        <source>on</source>
        <translation>an</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>your run: %1</source>
        <translation>dein Lauf: %1</translation>
    </message>
    <message>
        <source>departs here, step %1</source>
        <translation>weicht hier ab, Schritt %1</translation>
    </message>
    <message>
        <source>Paused at t = 0 · press Space to run</source>
        <translation>Pausiert bei t = 0 · drücke die Leertaste zum Starten</translation>
    </message>
    <message>
        <source>Tools: press %1</source>
        <translation>Werkzeuge: drücke %1</translation>
    </message>
    <message>
        <source>⚠ %1</source>
        <translation>⚠ %1</translation>
    </message>
    <message>
        <source>Set the velocity of ball %1</source>
        <translation>Geschwindigkeit von Kugel %1 setzen</translation>
    </message>
    <message>
        <source>Move ball %1</source>
        <translation>Kugel %1 verschieben</translation>
    </message>
    <message>
        <source>Add a ball</source>
        <translation>Kugel hinzufügen</translation>
    </message>
    <message>
        <source>Nothing to paste: %1</source>
        <translation>Nichts einzufügen: %1</translation>
    </message>
    <message>
        <source>Paste a ball</source>
        <translation>Kugel einfügen</translation>
    </message>
    <message>
        <source>Ball %1</source>
        <translation>Kugel %1</translation>
    </message>
    <message>
        <source>Edit its numbers…</source>
        <translation>Zahlen bearbeiten …</translation>
    </message>
    <message>
        <source>Stop it (v = 0)</source>
        <translation>Anhalten (v = 0)</translation>
    </message>
    <message>
        <source>Stop ball %1</source>
        <translation>Kugel %1 anhalten</translation>
    </message>
    <message>
        <source>Pin</source>
        <translation>Festhalten</translation>
    </message>
    <message>
        <source>Pin ball %1</source>
        <translation>Kugel %1 festhalten</translation>
    </message>
    <message>
        <source>Free ball %1</source>
        <translation>Kugel %1 freigeben</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplizieren</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Kopieren</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Follow it</source>
        <translation>Ihr folgen</translation>
    </message>
    <message>
        <source>Add a ball here</source>
        <translation>Hier eine Kugel hinzufügen</translation>
    </message>
    <message>
        <source>Paste the copied ball here</source>
        <translation>Kopierte Kugel hier einfügen</translation>
    </message>
    <message>
        <source>Zoom in here</source>
        <translation>Hier vergrößern</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Verkleinern</translation>
    </message>
    <message>
        <source>Fit the box</source>
        <translation>Kasten einpassen</translation>
    </message>
    <message>
        <source>Fit all balls</source>
        <translation>Alle Kugeln einpassen</translation>
    </message>
</context>
<context>
    <name>forcelab::CodeDock</name>
    <message>
        <source>Code</source>
        <translation>Code</translation>
    </message>
    <message>
        <source>The simulation code of this stage</source>
        <translation>Der Simulationscode dieser Stufe</translation>
    </message>
    <message>
        <source>C++</source>
        <translation>C++</translation>
    </message>
    <message>
        <source>The engine&apos;s own code (sim/)</source>
        <translation>Der eigene Code der Engine (sim/)</translation>
    </message>
    <message>
        <source>JavaScript</source>
        <translation>JavaScript</translation>
    </message>
    <message>
        <source>The code students write in the programming course (lessons/code/)</source>
        <translation>Der Code, den Schülerinnen und Schüler im Programmierkurs schreiben (lessons/code/)</translation>
    </message>
    <message>
        <source>&lt;p&gt;This stage runs no marked code.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Diese Stufe führt keinen markierten Code aus.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>, runs when %1 = %2</source>
        <translation>, läuft, wenn %1 = %2</translation>
    </message>
    <message>
        <source>&lt;p&gt;The code of this stage in JavaScript, as students write it. It runs beside the engine and moves the balls the same, to the last bit (test_script_reference).&lt;/p&gt;</source>
        <translation>&lt;p&gt;Der Code dieser Stufe in JavaScript, so wie Schülerinnen und Schüler ihn schreiben. Er läuft neben der Engine und bewegt die Kugeln genauso, bis aufs letzte Bit (test_script_reference).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p class=&apos;missing&apos;&gt;Not written in JavaScript yet: %1.&lt;/p&gt;</source>
        <translation>&lt;p class=&apos;missing&apos;&gt;Noch nicht in JavaScript geschrieben: %1.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>forcelab::EnergyBars</name>
    <message>
        <source>kinetic</source>
        <translation>kinetisch</translation>
    </message>
    <message>
        <source>potential</source>
        <translation>potenziell</translation>
    </message>
    <message>
        <source>lost</source>
        <translation>verloren</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>Energy bars: kinetic, potential, lost and total energy now</source>
        <translation>Energiebalken: kinetische, potenzielle, verlorene und gesamte Energie jetzt</translation>
    </message>
    <message>
        <source>Energy now</source>
        <translation>Energie jetzt</translation>
    </message>
    <message>
        <source>Lost: energy taken out by drag, bumpy collisions and walls since the bars were shown or the lesson restarted. Energy put in (wind, your hand, an edit) counts as negative lost energy, so the total stays the same unless the computer&apos;s steps are inaccurate.</source>
        <translation>Verloren: Energie, die seit dem Einblenden der Balken oder dem Neustart der Lektion durch Luftwiderstand, unelastische Stöße und Wände entzogen wurde. Zugeführte Energie (Wind, deine Hand, eine Änderung) zählt als negative verlorene Energie, daher bleibt die Summe gleich, außer die Schritte des Computers sind ungenau.</translation>
    </message>
    <message>
        <source>energy (%1%2)</source>
        <translation>Energie (%1%2)</translation>
    </message>
    <message>
        <source>not counted</source>
        <translation>nicht gezählt</translation>
    </message>
</context>
<context>
    <name>forcelab::ForceEditorDock</name>
    <message>
        <source>Force editor</source>
        <translation>Kraft-Editor</translation>
    </message>
    <message>
        <source>Write your own force law. Use x, y (px), vx, vy (px/s), m, r, q, the time t, the box W and H, pi, functions such as sqrt, sin, exp, and your constants.</source>
        <translation>Schreibe dein eigenes Kraftgesetz. Verwende x, y (px), vx, vy (px/s), m, r, q, die Zeit t, den Kasten W und H, pi, Funktionen wie sqrt, sin, exp und deine Konstanten.</translation>
    </message>
    <message>
        <source>Custom force on</source>
        <translation>Eigene Kraft an</translation>
    </message>
    <message>
        <source>the formulas give the force F (divided by m)</source>
        <translation>die Formeln ergeben die Kraft F (geteilt durch m)</translation>
    </message>
    <message>
        <source>the formulas give the acceleration a</source>
        <translation>die Formeln ergeben die Beschleunigung a</translation>
    </message>
    <message>
        <source>What the formulas give</source>
        <translation>Was die Formeln ergeben</translation>
    </message>
    <message>
        <source>F_x =</source>
        <translation>F_x =</translation>
    </message>
    <message>
        <source>The x part of the force (or acceleration)</source>
        <translation>Der x-Anteil der Kraft (oder Beschleunigung)</translation>
    </message>
    <message>
        <source>F_y =</source>
        <translation>F_y =</translation>
    </message>
    <message>
        <source>The y part; y points down</source>
        <translation>Der y-Anteil; y zeigt nach unten</translation>
    </message>
    <message>
        <source>U =</source>
        <translation>U =</translation>
    </message>
    <message>
        <source>Optional: the potential energy of a conservative law, with F = −∇U</source>
        <translation>Optional: die potenzielle Energie eines konservativen Gesetzes, mit F = −∇U</translation>
    </message>
    <message>
        <source>&lt;b&gt;Constants&lt;/b&gt;</source>
        <translation>&lt;b&gt;Konstanten&lt;/b&gt;</translation>
    </message>
    <message>
        <source>name, e.g. k</source>
        <translation>Name, z. B. k</translation>
    </message>
    <message>
        <source>New constant&apos;s name</source>
        <translation>Name der neuen Konstante</translation>
    </message>
    <message>
        <source>Add constant</source>
        <translation>Konstante hinzufügen</translation>
    </message>
    <message>
        <source>Constant %1</source>
        <translation>Konstante %1</translation>
    </message>
    <message>
        <source>Add constant %1</source>
        <translation>Konstante %1 hinzufügen</translation>
    </message>
    <message>
        <source>Custom force: %1</source>
        <translation>Eigene Kraft: %1</translation>
    </message>
</context>
<context>
    <name>forcelab::InspectorDock</name>
    <message>
        <source>Inspector</source>
        <translation>Inspektor</translation>
    </message>
    <message>
        <source>Click a ball to see its numbers.</source>
        <translation>Klicke auf eine Kugel, um ihre Zahlen zu sehen.</translation>
    </message>
    <message>
        <source>Ball</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <source>Position x</source>
        <translation>Position x</translation>
    </message>
    <message>
        <source>Velocity v</source>
        <translation>Geschwindigkeit v</translation>
    </message>
    <message>
        <source>Acceleration a</source>
        <translation>Beschleunigung a</translation>
    </message>
    <message>
        <source>Mass, radius</source>
        <translation>Masse, Radius</translation>
    </message>
    <message>
        <source>Draw its trail</source>
        <translation>Spur zeichnen</translation>
    </message>
    <message>
        <source>#%1 of %2</source>
        <translation>#%1 von %2</translation>
    </message>
    <message>
        <source>m = %1 %2, r = %3 %4</source>
        <translation>m = %1 %2, r = %3 %4</translation>
    </message>
    <message>
        <source>m = %1, r = %2 px</source>
        <translation>m = %1, r = %2 px</translation>
    </message>
    <message>
        <source>Forces F = m a</source>
        <translation>Kräfte F = m a</translation>
    </message>
    <message>
        <source>no force acts</source>
        <translation>keine Kraft wirkt</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>in %1</source>
        <translation>in %1</translation>
    </message>
</context>
<context>
    <name>forcelab::LessonTextView</name>
    <message>
        <source>Open a web page?</source>
        <translation>Webseite öffnen?</translation>
    </message>
    <message>
        <source>The lesson links to
%1

Open it in your web browser?</source>
        <translation>Die Lektion verweist auf
%1

In deinem Webbrowser öffnen?</translation>
    </message>
</context>
<context>
    <name>forcelab::LessonsDock</name>
    <message>
        <source>Lessons</source>
        <translation>Lektionen</translation>
    </message>
    <message>
        <source>Teacher notes</source>
        <translation>Hinweise für Lehrkräfte</translation>
    </message>
    <message>
        <source>Show the goal, expected answers and misconceptions under the lesson text</source>
        <translation>Ziel, erwartete Antworten und Fehlvorstellungen unter dem Lektionstext zeigen</translation>
    </message>
    <message>
        <source>Part A · Motion and walls</source>
        <translation>Teil A · Bewegung und Wände</translation>
    </message>
    <message>
        <source>Part B · Forces</source>
        <translation>Teil B · Kräfte</translation>
    </message>
    <message>
        <source>Part C · Collisions</source>
        <translation>Teil C · Stöße</translation>
    </message>
    <message>
        <source>Beyond the course</source>
        <translation>Über den Kurs hinaus</translation>
    </message>
    <message>
        <source>Stage %1 of 29</source>
        <translation>Stufe %1 von 29</translation>
    </message>
    <message>
        <source>Beyond the course · %1</source>
        <translation>Über den Kurs hinaus · %1</translation>
    </message>
    <message>
        <source>Try this</source>
        <translation>Probier das aus</translation>
    </message>
    <message>
        <source>For the teacher</source>
        <translation>Für die Lehrkraft</translation>
    </message>
    <message>
        <source>&lt;p&gt;This lesson has no teacher notes.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Diese Lektion hat keine Hinweise für Lehrkräfte.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>forcelab::MainWindow</name>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Balls</source>
        <translation>Kugeln</translation>
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
        <source>The computer could not keep up: simulated time was skipped</source>
        <translation>Der Computer kam nicht hinterher: Simulierte Zeit wurde übersprungen</translation>
    </message>
    <message>
        <source>Simulated time</source>
        <translation>Simulierte Zeit</translation>
    </message>
    <message>
        <source>Simulated seconds per real second ([ slower, ] faster)</source>
        <translation>Simulierte Sekunden pro echter Sekunde ([ langsamer, ] schneller)</translation>
    </message>
    <message>
        <source>Frames drawn per second, and the time to draw one</source>
        <translation>Gezeichnete Bilder pro Sekunde und die Zeit für eines</translation>
    </message>
    <message>
        <source>Wall-clock time of the last simulation step</source>
        <translation>Echte Dauer des letzten Simulationsschritts</translation>
    </message>
    <message>
        <source>Number of balls</source>
        <translation>Anzahl der Kugeln</translation>
    </message>
    <message>
        <source>Ball pairs tested for contact in the last step, and the contacts found</source>
        <translation>Im letzten Schritt auf Berührung geprüfte Kugelpaare und die gefundenen Berührungen</translation>
    </message>
    <message>
        <source>%1: %2: %3</source>
        <translation>%1: %2: %3</translation>
    </message>
    <message>
        <source>not a saved window geometry; using the default size</source>
        <translation>keine gespeicherte Fenstergeometrie; Standardgröße wird verwendet</translation>
    </message>
    <message>
        <source>not a saved layout of the docks; using the default layout</source>
        <translation>keine gespeicherte Anordnung der Leisten; Standardanordnung wird verwendet</translation>
    </message>
    <message>
        <source>%1 is not a folder; using the home folder</source>
        <translation>%1 ist kein Ordner; der persönliche Ordner wird verwendet</translation>
    </message>
    <message>
        <source>not true or false; using the plain theme</source>
        <translation>weder true noch false; das normale Design wird verwendet</translation>
    </message>
    <message>
        <source>not a text size from %1 to %2; using the usual size</source>
        <translation>keine Textgröße von %1 bis %2; die übliche Größe wird verwendet</translation>
    </message>
    <message>
        <source>%1: %2: %3; opened the first lesson instead</source>
        <translation>%1: %2: %3; stattdessen wurde die erste Lektion geöffnet</translation>
    </message>
    <message>
        <source>no built-in lessons were found</source>
        <translation>keine eingebauten Lektionen gefunden</translation>
    </message>
    <message>
        <source>ForceLab</source>
        <translation>ForceLab</translation>
    </message>
    <message>
        <source>%1 — ForceLab</source>
        <translation>%1 — ForceLab</translation>
    </message>
    <message>
        <source>Already the slowest speed, %1×</source>
        <translation>Schon das langsamste Tempo, %1×</translation>
    </message>
    <message>
        <source>Already the fastest speed, %1×</source>
        <translation>Schon das schnellste Tempo, %1×</translation>
    </message>
    <message>
        <source>Speed %1×</source>
        <translation>Tempo %1×</translation>
    </message>
    <message>
        <source>Cannot open lesson</source>
        <translation>Lektion kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>The lesson could not be opened; the running lesson goes on.</source>
        <translation>Die Lektion konnte nicht geöffnet werden; die laufende Lektion geht weiter.</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more. Show Details… lists every problem.</source>
        <translation>
            <numerusform>… und %n weiteres. „Details einblenden...“ listet jedes Problem auf.</numerusform>
            <numerusform>… und %n weitere. „Details einblenden...“ listet jedes Problem auf.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Text at %1% of its usual size (Ctrl+= larger, Ctrl+− smaller, Ctrl+0 usual)</source>
        <translation>Text bei %1 % der üblichen Größe (Ctrl+= größer, Ctrl+− kleiner, Ctrl+0 üblich)</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>speed %1×</source>
        <translation>Tempo %1×</translation>
    </message>
    <message>
        <source>%1 fps · draw %2 ms</source>
        <translation>%1 fps · Zeichnen %2 ms</translation>
    </message>
    <message>
        <source>step %1 µs</source>
        <translation>Schritt %1 µs</translation>
    </message>
    <message>
        <source>1 ball</source>
        <translation>1 Kugel</translation>
    </message>
    <message>
        <source>%L1 balls</source>
        <translation>%L1 Kugeln</translation>
    </message>
    <message>
        <source>pairs tested %L1 · contacts %L2</source>
        <translation>geprüfte Paare %L1 · Berührungen %L2</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Start</translation>
    </message>
    <message>
        <source>Pause the simulation (Space)</source>
        <translation>Simulation anhalten (Space)</translation>
    </message>
    <message>
        <source>Run the simulation (Space)</source>
        <translation>Simulation starten (Space)</translation>
    </message>
    <message>
        <source>⚠ %1</source>
        <translation>⚠ %1</translation>
    </message>
    <message>
        <source>behind: %1 ms skipped</source>
        <translation>im Rückstand: %1 ms übersprungen</translation>
    </message>
    <message>
        <source>About ForceLab</source>
        <translation>Über ForceLab</translation>
    </message>
    <message>
        <source>&lt;b&gt;ForceLab&lt;/b&gt; %1&lt;br&gt;A workbench for forces and collisions of balls in two dimensions.</source>
        <translation>&lt;b&gt;ForceLab&lt;/b&gt; %1&lt;br&gt;Eine Werkbank für Kräfte und Stöße von Kugeln in zwei Dimensionen.</translation>
    </message>
    <message>
        <source>Step &amp;Back</source>
        <translation>Schritt zu&amp;rück</translation>
    </message>
    <message>
        <source>Pause and go back by one time step dt, to the world as it was (← or ,)</source>
        <translation>Anhalten und um einen Zeitschritt dt zurückgehen, zur Welt, wie sie war (← oder ,)</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <source>&amp;Step</source>
        <translation>&amp;Schritt</translation>
    </message>
    <message>
        <source>Pause and advance by one time step dt (→ or .)</source>
        <translation>Anhalten und um einen Zeitschritt dt weitergehen (→ oder .)</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>Start the lesson again with its own values (R)</source>
        <translation>Die Lektion mit ihren eigenen Werten neu starten (R)</translation>
    </message>
    <message>
        <source>S&amp;lower</source>
        <translation>&amp;Langsamer</translation>
    </message>
    <message>
        <source>Half the speed: slow motion down to 1/16× ([)</source>
        <translation>Halbes Tempo: Zeitlupe bis zu 1/16× ([)</translation>
    </message>
    <message>
        <source>&amp;Faster</source>
        <translation>Sc&amp;hneller</translation>
    </message>
    <message>
        <source>Double the speed, up to %1× (])</source>
        <translation>Doppeltes Tempo, bis zu %1× (])</translation>
    </message>
    <message>
        <source>&amp;Add Ball</source>
        <translation>Kugel &amp;hinzufügen</translation>
    </message>
    <message>
        <source>Add a ball in the middle of the box (B). Right-click the stage to add one where you click.</source>
        <translation>Eine Kugel in der Mitte des Kastens hinzufügen (B). Rechtsklicke auf die Bühne, um eine dort hinzuzufügen, wo du klickst.</translation>
    </message>
    <message>
        <source>&amp;Delete Ball</source>
        <translation>Kugel &amp;löschen</translation>
    </message>
    <message>
        <source>D&amp;uplicate Ball</source>
        <translation>Kugel d&amp;uplizieren</translation>
    </message>
    <message>
        <source>&amp;Copy Ball</source>
        <translation>Kugel &amp;kopieren</translation>
    </message>
    <message>
        <source>&amp;Paste Ball</source>
        <translation>Kugel ei&amp;nfügen</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>&amp;Vergrößern</translation>
    </message>
    <message>
        <source>Zoom in on the middle (+); the mouse wheel zooms in on the pointer</source>
        <translation>Zur Mitte hin vergrößern (+); das Mausrad vergrößert zum Mauszeiger hin</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>Verklei&amp;nern</translation>
    </message>
    <message>
        <source>Zoom out (−), to see balls that left the box</source>
        <translation>Verkleinern (−), um Kugeln zu sehen, die den Kasten verlassen haben</translation>
    </message>
    <message>
        <source>Fit the &amp;Box</source>
        <translation>Kasten ein&amp;passen</translation>
    </message>
    <message>
        <source>Show the whole box, as large as it fits (0)</source>
        <translation>Den ganzen Kasten zeigen, so groß wie er passt (0)</translation>
    </message>
    <message>
        <source>Fit &amp;All Balls</source>
        <translation>Alle K&amp;ugeln einpassen</translation>
    </message>
    <message>
        <source>Zoom so that every ball is seen, in the box or out of it (A)</source>
        <translation>So zoomen, dass jede Kugel zu sehen ist, im Kasten oder außerhalb (A)</translation>
    </message>
    <message>
        <source>&amp;Follow the Selected Ball</source>
        <translation>Der ausgewählten Kugel &amp;folgen</translation>
    </message>
    <message>
        <source>Keep the selected ball in the middle of the view as it moves (F)</source>
        <translation>Die ausgewählte Kugel in der Mitte der Ansicht halten, während sie sich bewegt (F)</translation>
    </message>
    <message>
        <source>&amp;Open Lesson…</source>
        <translation>Lektion &amp;öffnen …</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Öffnen</translation>
    </message>
    <message>
        <source>Open a lesson file from disk</source>
        <translation>Eine Lektionsdatei vom Datenträger öffnen</translation>
    </message>
    <message>
        <source>&amp;Save Scene as Lesson…</source>
        <translation>Szene als Lektion &amp;speichern …</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Speichern</translation>
    </message>
    <message>
        <source>Save the balls as they are now and the live settings as a lesson file</source>
        <translation>Die Kugeln, wie sie jetzt sind, und die aktuellen Einstellungen als Lektionsdatei speichern</translation>
    </message>
    <message>
        <source>Screens&amp;hot…</source>
        <translation>Bildschirm&amp;foto …</translation>
    </message>
    <message>
        <source>Picture</source>
        <translation>Bild</translation>
    </message>
    <message>
        <source>Save a picture of the canvas as PNG</source>
        <translation>Ein Bild der Zeichenfläche als PNG speichern</translation>
    </message>
    <message>
        <source>Re&amp;cord Trajectory</source>
        <translation>Bahn &amp;aufzeichnen</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Aufzeichnen</translation>
    </message>
    <message>
        <source>Record the path of the selected ball (or of all balls when none is selected)</source>
        <translation>Die Bahn der ausgewählten Kugel aufzeichnen (oder aller Kugeln, wenn keine ausgewählt ist)</translation>
    </message>
    <message>
        <source>Recording ball #%1</source>
        <translation>Zeichne Kugel #%1 auf</translation>
    </message>
    <message>
        <source>Recording every ball</source>
        <translation>Zeichne jede Kugel auf</translation>
    </message>
    <message>
        <source>&amp;Export Trajectory…</source>
        <translation>Bahn &amp;exportieren …</translation>
    </message>
    <message>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <source>Write the recorded trajectory as CSV (time, ball, position, velocity)</source>
        <translation>Die aufgezeichnete Bahn als CSV schreiben (Zeit, Kugel, Position, Geschwindigkeit)</translation>
    </message>
    <message>
        <source>Export Teacher &amp;Handbook…</source>
        <translation>&amp;Handbuch für Lehrkräfte exportieren …</translation>
    </message>
    <message>
        <source>Write every lesson with its teacher notes as one printable HTML page</source>
        <translation>Jede Lektion mit ihren Hinweisen für Lehrkräfte als eine druckbare HTML-Seite schreiben</translation>
    </message>
    <message>
        <source>&amp;Previous Lesson</source>
        <translation>&amp;Vorherige Lektion</translation>
    </message>
    <message>
        <source>&amp;Next Lesson</source>
        <translation>&amp;Nächste Lektion</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Stage View (Projector)</source>
        <translation>&amp;Bühnenansicht (Beamer)</translation>
    </message>
    <message>
        <source>The simulation fills the screen with large controls beside it, for a projector (F11; Escape leaves)</source>
        <translation>Die Simulation füllt den Bildschirm, mit großen Bedienelementen daneben, für einen Beamer (F11; Escape beendet)</translation>
    </message>
    <message>
        <source>Stage</source>
        <translation>Bühne</translation>
    </message>
    <message>
        <source>&amp;Larger Text</source>
        <translation>&amp;Größerer Text</translation>
    </message>
    <message>
        <source>Larger text in every panel and on the stage (Ctrl+=)</source>
        <translation>Größerer Text in jeder Leiste und auf der Bühne (Ctrl+=)</translation>
    </message>
    <message>
        <source>S&amp;maller Text</source>
        <translation>&amp;Kleinerer Text</translation>
    </message>
    <message>
        <source>Smaller text in every panel and on the stage (Ctrl+−)</source>
        <translation>Kleinerer Text in jeder Leiste und auf der Bühne (Ctrl+−)</translation>
    </message>
    <message>
        <source>&amp;Usual Text Size</source>
        <translation>Übliche &amp;Textgröße</translation>
    </message>
    <message>
        <source>P&amp;rojector Theme</source>
        <translation>Bea&amp;mer-Design</translation>
    </message>
    <message>
        <source>White box, dark thick outlines, colour-blind-safe balls and larger text everywhere (always on in the stage view)</source>
        <translation>Weißer Kasten, dunkle dicke Umrisse, farbenblind-sichere Kugeln und überall größerer Text (in der Bühnenansicht immer an)</translation>
    </message>
    <message>
        <source>Picture at &amp;Double Size…</source>
        <translation>Bild in &amp;doppelter Größe …</translation>
    </message>
    <message>
        <source>Save the stage at twice the screen&apos;s resolution, for print</source>
        <translation>Die Bühne in doppelter Bildschirmauflösung speichern, für den Druck</translation>
    </message>
    <message>
        <source>&amp;About ForceLab</source>
        <translation>Ü&amp;ber ForceLab</translation>
    </message>
    <message>
        <source>&amp;Pixels</source>
        <translation>&amp;Pixel</translation>
    </message>
    <message>
        <source>Show px, px/s and mass units, as the program computes them</source>
        <translation>px, px/s und Masseneinheiten zeigen, wie das Programm sie berechnet</translation>
    </message>
    <message>
        <source>&amp;SI (m, kg, N, J)</source>
        <translation>&amp;SI (m, kg, N, J)</translation>
    </message>
    <message>
        <source>Show metres, kilograms, newtons and joules at the scale set below</source>
        <translation>Meter, Kilogramm, Newton und Joule im unten eingestellten Maßstab zeigen</translation>
    </message>
    <message>
        <source>How many pixels make a metre, and how many kilograms a mass unit</source>
        <translation>Wie viele Pixel einen Meter ergeben und wie viele Kilogramm eine Masseneinheit</translation>
    </message>
    <message>
        <source>SI Scale</source>
        <translation>SI-Maßstab</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source> kg</source>
        <translation> kg</translation>
    </message>
    <message>
        <source>1 m is</source>
        <translation>1 m sind</translation>
    </message>
    <message>
        <source>1 mass unit is</source>
        <translation>1 Masseneinheit sind</translation>
    </message>
    <message>
        <source>SI &amp;Scale: %1 px = 1 m, 1 mass unit = %2 kg…</source>
        <translation>SI-&amp;Maßstab: %1 px = 1 m, 1 Masseneinheit = %2 kg …</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Bearbeiten</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;Lesson</source>
        <translation>&amp;Lektion</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Werkzeuge</translation>
    </message>
    <message>
        <source>&amp;Accuracy</source>
        <translation>&amp;Genauigkeit</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Units</source>
        <translation>&amp;Einheiten</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>Show</source>
        <translation>Anzeigen</translation>
    </message>
    <message>
        <source>Show: what the stage draws</source>
        <translation>Anzeigen: was die Bühne zeichnet</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>Open Lesson</source>
        <translation>Lektion öffnen</translation>
    </message>
    <message>
        <source>Lesson files (*.json);;All files (*)</source>
        <translation>Lektionsdateien (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Lesson not saved: %1</source>
        <translation>Lektion nicht gespeichert: %1</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n ball(s) and the settings to %1 as “%2”. %3</source>
        <translation>
            <numerusform>%n Kugel und die Einstellungen in %1 als „%2“ gespeichert. %3</numerusform>
            <numerusform>%n Kugeln und die Einstellungen in %1 als „%2“ gespeichert. %3</numerusform>
        </translation>
    </message>
    <message>
        <source>Picture not saved: %1</source>
        <translation>Bild nicht gespeichert: %1</translation>
    </message>
    <message>
        <source>Saved the picture to %1</source>
        <translation>Bild in %1 gespeichert</translation>
    </message>
    <message>
        <source>Save Picture at Double Size</source>
        <translation>Bild in doppelter Größe speichern</translation>
    </message>
    <message>
        <source>Save Picture</source>
        <translation>Bild speichern</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>PNG-Bilder (*.png)</translation>
    </message>
    <message>
        <source>Export Teacher Handbook</source>
        <translation>Handbuch für Lehrkräfte exportieren</translation>
    </message>
    <message>
        <source>HTML (*.html)</source>
        <translation>HTML (*.html)</translation>
    </message>
    <message>
        <source>%1
The handbook was not written; an old file there is unchanged.</source>
        <translation>%1
Das Handbuch wurde nicht geschrieben; eine alte Datei dort bleibt unverändert.</translation>
    </message>
    <message>
        <source>Handbook written to %1</source>
        <translation>Handbuch in %1 geschrieben</translation>
    </message>
    <message>
        <source>Nothing recorded yet: switch on Record Trajectory (Ctrl+Shift+R) first</source>
        <translation>Noch nichts aufgezeichnet: Schalte zuerst „Bahn aufzeichnen“ (Ctrl+Shift+R) ein</translation>
    </message>
    <message>
        <source>Export Trajectory</source>
        <translation>Bahn exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Wrote %L1 rows to %2</source>
        <translation>%L1 Zeilen in %2 geschrieben</translation>
    </message>
    <message>
        <source>&amp;Describe the Scene</source>
        <translation>Szene &amp;beschreiben</translation>
    </message>
    <message>
        <source>Say in words what is on the stage: the balls, the selected one&apos;s motion, when it reaches a wall, the energy (D)</source>
        <translation>Sagt in Worten, was auf der Bühne ist: die Kugeln, die Bewegung der ausgewählten, wann sie eine Wand erreicht, die Energie (D)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>Reset</source>
        <comment>the word under the button&apos;s icon: short, it has 72 px on the stage</comment>
        <translation>Reset</translation>
    </message>
    <message>
        <source>Slower</source>
        <comment>the word under the button&apos;s icon: short, it has 72 px on the stage</comment>
        <translation>Langsam</translation>
    </message>
    <message>
        <source>Faster</source>
        <comment>the word under the button&apos;s icon: short, it has 72 px on the stage</comment>
        <translation>Schnell</translation>
    </message>
</context>
<context>
    <name>forcelab::NumberControl</name>
    <message>
        <source>%1, slider</source>
        <translation>%1, Schieberegler</translation>
    </message>
    <message>
        <source>%1, value</source>
        <translation>%1, Wert</translation>
    </message>
</context>
<context>
    <name>forcelab::OverlayActions</name>
    <message>
        <source>&amp;Show</source>
        <translation>An&amp;zeigen</translation>
    </message>
    <message>
        <source>&amp;Velocity arrows</source>
        <translation>&amp;Geschwindigkeitspfeile</translation>
    </message>
    <message>
        <source>&amp;Acceleration arrows (a = F/m)</source>
        <translation>&amp;Beschleunigungspfeile (a = F/m)</translation>
    </message>
    <message>
        <source>&amp;Force arrows (net force F = m a)</source>
        <translation>&amp;Kraftpfeile (resultierende Kraft F = m a)</translation>
    </message>
    <message>
        <source>Forces &amp;by source (one arrow per force)</source>
        <translation>Kräfte nach &amp;Ursache (ein Pfeil pro Kraft)</translation>
    </message>
    <message>
        <source>&amp;Paths</source>
        <translation>&amp;Spuren</translation>
    </message>
    <message>
        <source>&amp;Centre of mass and its path</source>
        <translation>S&amp;chwerpunkt und seine Spur</translation>
    </message>
    <message>
        <source>M&amp;omenta diagram (p = m v, tip to tail)</source>
        <translation>&amp;Impulsdiagramm (p = m v, Spitze an Ende)</translation>
    </message>
    <message>
        <source>Tops of the flights, with their &amp;heights</source>
        <translation>Scheitelpunkte der Flüge, mit ihren &amp;Höhen</translation>
    </message>
    <message>
        <source>&amp;Readout of the selected ball</source>
        <translation>&amp;Werte der ausgewählten Kugel</translation>
    </message>
    <message>
        <source>&amp;Totals: energy and momentum</source>
        <translation>Summen: Energie und Im&amp;puls</translation>
    </message>
    <message>
        <source>&amp;Mark touching balls</source>
        <translation>Sich berührende Kugeln &amp;markieren</translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation>Gitte&amp;r</translation>
    </message>
    <message>
        <source>&amp;Markers (centres, anchors, homes)</source>
        <translation>Markierunge&amp;n (Mittelpunkte, Anker, Ruhelagen)</translation>
    </message>
    <message>
        <source>Arrow &amp;length</source>
        <translation>Pfeil&amp;länge</translation>
    </message>
    <message>
        <source>&amp;Auto: readable (about 45 px)</source>
        <translation>&amp;Automatisch: lesbar (etwa 45 px)</translation>
    </message>
    <message>
        <source>The lesson&apos;s scale (×1)</source>
        <translation>Maßstab der Lektion (×1)</translation>
    </message>
    <message>
        <source>×%1 the lesson&apos;s scale</source>
        <translation>×%1 Maßstab der Lektion</translation>
    </message>
    <message>
        <source>Arrow scale ×&amp;2</source>
        <translation>Pfeilmaßstab ×&amp;2</translation>
    </message>
    <message>
        <source>Arrow scale ÷2</source>
        <translation>Pfeilmaßstab ÷2</translation>
    </message>
    <message>
        <source>Arrow scale &amp;from now</source>
        <translation>Pfeilmaßstab a&amp;b jetzt</translation>
    </message>
</context>
<context>
    <name>forcelab::ParameterPanel</name>
    <message>
        <source>Show all parameters</source>
        <translation>Alle Parameter zeigen</translation>
    </message>
    <message>
        <source>Besides the lesson&apos;s own controls, show every setting of the world</source>
        <translation>Neben den Reglern der Lektion jede Einstellung der Welt zeigen</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Schwerkraft</translation>
    </message>
    <message>
        <source>Box and walls</source>
        <translation>Kasten und Wände</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Luftwiderstand</translation>
    </message>
    <message>
        <source>Wind</source>
        <translation>Wind</translation>
    </message>
    <message>
        <source>Random acceleration</source>
        <translation>Zufallsbeschleunigung</translation>
    </message>
    <message>
        <source>Point force</source>
        <translation>Punktkraft</translation>
    </message>
    <message>
        <source>Spring</source>
        <translation>Feder</translation>
    </message>
    <message>
        <source>Gravity between balls</source>
        <translation>Gravitation zwischen Kugeln</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Rückholkraft</translation>
    </message>
    <message>
        <source>Pointer force</source>
        <translation>Mauszeiger-Kraft</translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation>Tempolimit</translation>
    </message>
    <message>
        <source>Collisions</source>
        <translation>Stöße</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Balls</source>
        <translation>Kugeln</translation>
    </message>
    <message numerus="yes">
        <source>%n more setting(s) under &quot;Show all parameters&quot;.</source>
        <translation>
            <numerusform>%n weitere Einstellung unter „Alle Parameter zeigen“.</numerusform>
            <numerusform>%n weitere Einstellungen unter „Alle Parameter zeigen“.</numerusform>
        </translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>%1 ändern</translation>
    </message>
    <message>
        <source>Tick to switch %1 on</source>
        <translation>Ankreuzen, um %1 einzuschalten</translation>
    </message>
    <message>
        <source>%1 to %2%3</source>
        <translation>%1 bis %2%3</translation>
    </message>
    <message>
        <source>left</source>
        <translation>links</translation>
    </message>
    <message>
        <source>right</source>
        <translation>rechts</translation>
    </message>
    <message>
        <source>top</source>
        <translation>oben</translation>
    </message>
    <message>
        <source>bottom</source>
        <translation>unten</translation>
    </message>
    <message>
        <source>Walls</source>
        <translation>Wände</translation>
    </message>
    <message>
        <source>A wall that is not ticked is open</source>
        <translation>Eine nicht angekreuzte Wand ist offen</translation>
    </message>
    <message>
        <source>time.seed: &quot;%1&quot; is not a whole number from 0 to 18446744073709551615</source>
        <translation>time.seed: „%1“ ist keine ganze Zahl von 0 bis 18446744073709551615</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Startwert</translation>
    </message>
    <message>
        <source>Random numbers (wind, random acceleration) start from this seed when the balls are placed again</source>
        <translation>Zufallszahlen (Wind, Zufallsbeschleunigung) beginnen bei diesem Startwert, wenn die Kugeln neu platziert werden</translation>
    </message>
    <message numerus="yes">
        <source>Place %n random ball(s)</source>
        <translation>
            <numerusform>%n Zufallskugel platzieren</numerusform>
            <numerusform>%n Zufallskugeln platzieren</numerusform>
        </translation>
    </message>
    <message>
        <source>Place random balls</source>
        <translation>Zufallskugeln platzieren</translation>
    </message>
    <message>
        <source>Random balls</source>
        <translation>Zufallskugeln</translation>
    </message>
    <message>
        <source>How many balls are placed at random (besides the lesson&apos;s own); changing it starts again</source>
        <translation>Wie viele Kugeln zufällig platziert werden (neben denen der Lektion); eine Änderung startet neu</translation>
    </message>
    <message>
        <source>Slowest random ball</source>
        <translation>Langsamste Zufallskugel</translation>
    </message>
    <message>
        <source>Fastest random ball</source>
        <translation>Schnellste Zufallskugel</translation>
    </message>
    <message>
        <source>Random balls start with a speed of at least this; changing it starts again</source>
        <translation>Zufallskugeln starten mit mindestens diesem Tempo; eine Änderung startet neu</translation>
    </message>
    <message>
        <source>Random balls start with a speed of at most this; changing it starts again</source>
        <translation>Zufallskugeln starten mit höchstens diesem Tempo; eine Änderung startet neu</translation>
    </message>
    <message>
        <source>Place balls fully inside</source>
        <translation>Kugeln ganz innen platzieren</translation>
    </message>
    <message>
        <source>Let balls start partly outside</source>
        <translation>Kugeln teilweise außen starten lassen</translation>
    </message>
    <message>
        <source>Start fully inside</source>
        <translation>Ganz innen starten</translation>
    </message>
    <message>
        <source>Off: a ball&apos;s centre may be anywhere in the box, so it can start partly outside a wall (stage 4&apos;s bug). Changing it places the balls again</source>
        <translation>Aus: Der Mittelpunkt einer Kugel darf überall im Kasten liegen, sie kann also teilweise außerhalb einer Wand starten (der Fehler aus Stufe 4). Eine Änderung platziert die Kugeln neu</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Tempo</translation>
    </message>
    <message>
        <source>Simulated seconds per real second: below 1 is slow motion (%1× to %2×)</source>
        <translation>Simulierte Sekunden pro echter Sekunde: unter 1 ist Zeitlupe (%1× bis %2×)</translation>
    </message>
</context>
<context>
    <name>forcelab::PlotsDock</name>
    <message>
        <source>Plots</source>
        <translation>Diagramme</translation>
    </message>
    <message>
        <source>kinetic</source>
        <translation>kinetisch</translation>
    </message>
    <message>
        <source>potential</source>
        <translation>potenziell</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>|p|</source>
        <translation>|p|</translation>
    </message>
    <message>
        <source>p_x</source>
        <translation>p_x</translation>
    </message>
    <message>
        <source>p_y</source>
        <translation>p_y</translation>
    </message>
    <message>
        <source>one step</source>
        <translation>ein Schritt</translation>
    </message>
    <message>
        <source>Plots of energy, momentum and step cost</source>
        <translation>Diagramme von Energie, Impuls und Schrittaufwand</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <source>Energy bars</source>
        <translation>Energiebalken</translation>
    </message>
    <message>
        <source>Graph</source>
        <translation>Graph</translation>
    </message>
    <message>
        <source>Momentum</source>
        <translation>Impuls</translation>
    </message>
    <message>
        <source>Cost of a step</source>
        <translation>Aufwand eines Schritts</translation>
    </message>
    <message>
        <source>Step cost</source>
        <translation>Schrittaufwand</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>Momentum (×10¹² mass·px²/s²)</source>
        <translation>Impuls (×10¹² Masse·px²/s²)</translation>
    </message>
    <message>
        <source>Speeds</source>
        <translation>Geschwindigkeiten</translation>
    </message>
    <message>
        <source>Computer time per step</source>
        <translation>Rechenzeit pro Schritt</translation>
    </message>
    <message>
        <source>µs</source>
        <translation>µs</translation>
    </message>
</context>
<context>
    <name>forcelab::PredictDock</name>
    <message>
        <source>Predict</source>
        <translation>Vorhersage</translation>
    </message>
    <message>
        <source>Your prediction</source>
        <translation>Deine Vorhersage</translation>
    </message>
    <message>
        <source>your guess</source>
        <translation>deine Schätzung</translation>
    </message>
    <message>
        <source>Lock in and run</source>
        <translation>Festlegen und starten</translation>
    </message>
    <message>
        <source>Show the answer now</source>
        <translation>Antwort jetzt zeigen</translation>
    </message>
    <message>
        <source>Next question</source>
        <translation>Nächste Frage</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>This lesson asks no question before it runs.</source>
        <translation>Diese Lektion stellt keine Frage, bevor sie läuft.</translation>
    </message>
    <message>
        <source>Make your prediction while the lesson waits at t = 0, then run it.</source>
        <translation>Mach deine Vorhersage, während die Lektion bei t = 0 wartet, und starte sie dann.</translation>
    </message>
    <message>
        <source>Type a number first (for example 200).</source>
        <translation>Gib zuerst eine Zahl ein (zum Beispiel 200).</translation>
    </message>
    <message>
        <source>Pick an answer first.</source>
        <translation>Wähle zuerst eine Antwort.</translation>
    </message>
    <message>
        <source>Still stopping the last measurement; try again in a moment.</source>
        <translation>Die letzte Messung wird noch beendet; versuch es gleich noch einmal.</translation>
    </message>
    <message>
        <source>Locked in. Working out the answer…</source>
        <translation>Festgelegt. Die Antwort wird ermittelt …</translation>
    </message>
    <message>
        <source>Cancelled. Change your answer or lock it in again.</source>
        <translation>Abgebrochen. Ändere deine Antwort oder lege sie erneut fest.</translation>
    </message>
    <message>
        <source>Locked in. Watch: the answer comes at t = %1 s.</source>
        <translation>Festgelegt. Pass auf: Die Antwort kommt bei t = %1 s.</translation>
    </message>
    <message>
        <source>It could not be measured in this run (the lesson&apos;s sentence “%1”). Did a setting change it?</source>
        <translation>Es ließ sich in diesem Lauf nicht messen (der Satz der Lektion „%1“). Hat eine Einstellung es verändert?</translation>
    </message>
    <message>
        <source>You chose &lt;b&gt;%1&lt;/b&gt;. Measured: &lt;b&gt;%2 %3&lt;/b&gt;, so the answer is &lt;b&gt;%4&lt;/b&gt;. %5</source>
        <translation>Du hast &lt;b&gt;%1&lt;/b&gt; gewählt. Gemessen: &lt;b&gt;%2 %3&lt;/b&gt;, also ist die Antwort &lt;b&gt;%4&lt;/b&gt;. %5</translation>
    </message>
    <message>
        <source>Well predicted!</source>
        <translation>Gut vorhergesagt!</translation>
    </message>
    <message>
        <source>Why was it different?</source>
        <translation>Warum war es anders?</translation>
    </message>
    <message>
        <source> (%1%)</source>
        <translation> (%1 %)</translation>
    </message>
    <message>
        <source>You said &lt;b&gt;%1 %2&lt;/b&gt;. Measured: &lt;b&gt;%3 %2&lt;/b&gt;. You were %4 %2 off%5.</source>
        <translation>Du hast &lt;b&gt;%1 %2&lt;/b&gt; gesagt. Gemessen: &lt;b&gt;%3 %2&lt;/b&gt;. Du lagst %4 %2 daneben%5.</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;small&gt;The run measured what the lesson says: “%1”.&lt;/small&gt;</source>
        <translation>&lt;br&gt;&lt;small&gt;Der Lauf hat gemessen, was die Lektion sagt: „%1“.&lt;/small&gt;</translation>
    </message>
</context>
<context>
    <name>forcelab::QuantityGraph</name>
    <message>
        <source>x position</source>
        <translation>x-Position</translation>
    </message>
    <message>
        <source>y position</source>
        <translation>y-Position</translation>
    </message>
    <message>
        <source>velocity v_x</source>
        <translation>Geschwindigkeit v_x</translation>
    </message>
    <message>
        <source>velocity v_y</source>
        <translation>Geschwindigkeit v_y</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>Tempo</translation>
    </message>
    <message>
        <source>kinetic energy</source>
        <translation>kinetische Energie</translation>
    </message>
    <message>
        <source>potential energy</source>
        <translation>potenzielle Energie</translation>
    </message>
    <message>
        <source>total energy</source>
        <translation>Gesamtenergie</translation>
    </message>
    <message>
        <source>momentum p_x</source>
        <translation>Impuls p_x</translation>
    </message>
    <message>
        <source>momentum p_y</source>
        <translation>Impuls p_y</translation>
    </message>
    <message>
        <source>Quantity to graph</source>
        <translation>Darzustellende Größe</translation>
    </message>
    <message>
        <source>Ball to graph</source>
        <translation>Darzustellende Kugel</translation>
    </message>
    <message>
        <source>of</source>
        <translation>von</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>Zeit (s)</translation>
    </message>
    <message>
        <source>all balls</source>
        <translation>alle Kugeln</translation>
    </message>
    <message>
        <source>ball %1</source>
        <translation>Kugel %1</translation>
    </message>
    <message>
        <source>theory: E₀, nothing takes energy away</source>
        <translation>Theorie: E₀, nichts entzieht Energie</translation>
    </message>
    <message>
        <source>theory: x₀ + v₀t + ½gt²</source>
        <translation>Theorie: x₀ + v₀t + ½gt²</translation>
    </message>
    <message>
        <source>theory: x₀ + v₀t</source>
        <translation>Theorie: x₀ + v₀t</translation>
    </message>
    <message>
        <source>theory: y₀ + v₀t + ½gt²</source>
        <translation>Theorie: y₀ + v₀t + ½gt²</translation>
    </message>
    <message>
        <source>theory: y₀ + v₀t</source>
        <translation>Theorie: y₀ + v₀t</translation>
    </message>
    <message>
        <source>theory: v₀ + gt</source>
        <translation>Theorie: v₀ + gt</translation>
    </message>
    <message>
        <source>theory: v₀, constant</source>
        <translation>Theorie: v₀, konstant</translation>
    </message>
    <message>
        <source>theory: |v₀ + gt|</source>
        <translation>Theorie: |v₀ + gt|</translation>
    </message>
    <message>
        <source>theory: |v₀|, constant</source>
        <translation>Theorie: |v₀|, konstant</translation>
    </message>
    <message>
        <source>theory: ½m|v₀ + gt|²</source>
        <translation>Theorie: ½m|v₀ + gt|²</translation>
    </message>
    <message>
        <source>theory: ½m|v₀|², constant</source>
        <translation>Theorie: ½m|v₀|², konstant</translation>
    </message>
    <message>
        <source>theory: mgh, h of the flight</source>
        <translation>Theorie: mgh, h der Flugbahn</translation>
    </message>
    <message>
        <source>theory: 0, no gravity</source>
        <translation>Theorie: 0, keine Schwerkraft</translation>
    </message>
    <message>
        <source>theory: E₀, constant</source>
        <translation>Theorie: E₀, konstant</translation>
    </message>
    <message>
        <source>theory: m(v₀ + gt)</source>
        <translation>Theorie: m(v₀ + gt)</translation>
    </message>
    <message>
        <source>theory: mv₀, constant</source>
        <translation>Theorie: mv₀, konstant</translation>
    </message>
    <message>
        <source>%1 of %2 (%3%4)</source>
        <translation>%1 von %2 (%3%4)</translation>
    </message>
</context>
<context>
    <name>forcelab::SaveLessonDialog</name>
    <message>
        <source>Save Scene as Lesson</source>
        <translation>Szene als Lektion speichern</translation>
    </message>
    <message>
        <source>The scene is saved as a new lesson with your title and text. Of the claims and questions of “%1”, only those that still hold in this scene are kept; the others are listed after saving.</source>
        <translation>Die Szene wird als neue Lektion mit deinem Titel und Text gespeichert. Von den Aussagen und Fragen aus „%1“ bleiben nur die erhalten, die in dieser Szene noch gelten; die anderen werden nach dem Speichern aufgelistet.</translation>
    </message>
    <message>
        <source>Plain text; an empty line starts a new paragraph.</source>
        <translation>Einfacher Text; eine Leerzeile beginnt einen neuen Absatz.</translation>
    </message>
    <message>
        <source>&amp;Keep the teacher notes</source>
        <translation>&amp;Hinweise für Lehrkräfte behalten</translation>
    </message>
    <message>
        <source>The goal, the minutes and the misconceptions. The answers to the challenges are never kept: the new lesson has no challenges.</source>
        <translation>Das Ziel, die Minuten und die Fehlvorstellungen. Die Antworten zu den Aufgaben werden nie übernommen: Die neue Lektion hat keine Aufgaben.</translation>
    </message>
    <message>
        <source>C&amp;hoose…</source>
        <translation>&amp;Wählen …</translation>
    </message>
    <message>
        <source>&amp;Title:</source>
        <translation>&amp;Titel:</translation>
    </message>
    <message>
        <source>Te&amp;xt:</source>
        <translation>Te&amp;xt:</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Datei:</translation>
    </message>
    <message>
        <source>Lesson files (*.json)</source>
        <translation>Lektionsdateien (*.json)</translation>
    </message>
    <message>
        <source>The lesson needs a title.</source>
        <translation>Die Lektion braucht einen Titel.</translation>
    </message>
    <message>
        <source>“%1” has a number or a comparison (“%2”) that nothing measures on this scene, and a lesson must not say what it does not check. Write it without, or add a claim to the file later.</source>
        <translation>„%1“ enthält eine Zahl oder einen Vergleich („%2“), den in dieser Szene nichts misst, und eine Lektion darf nichts behaupten, was sie nicht prüft. Schreib es ohne, oder füge später eine Aussage in die Datei ein.</translation>
    </message>
    <message>
        <source>Choose the file to save to.</source>
        <translation>Wähle die Datei zum Speichern.</translation>
    </message>
</context>
<context>
    <name>forcelab::SettingsEditor</name>
    <message>
        <source>Random balls from %1 to %2 px/s</source>
        <translation>Zufallskugeln von %1 bis %2 px/s</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>mass: %1 is outside %2</source>
        <translation>Masse: %1 liegt außerhalb von %2</translation>
    </message>
    <message>
        <source>Not placed: %1</source>
        <translation>Nicht platziert: %1</translation>
    </message>
    <message>
        <source>Moved to (%1, %2) px, touching, so it does not overlap</source>
        <translation>Nach (%1, %2) px verschoben, berührend, damit sie nicht überlappt</translation>
    </message>
    <message>
        <source>Not added: the world holds at most %1 balls</source>
        <translation>Nicht hinzugefügt: Die Welt fasst höchstens %1 Kugeln</translation>
    </message>
    <message>
        <source>Delete ball %1</source>
        <translation>Kugel %1 löschen</translation>
    </message>
    <message>
        <source>Duplicate ball %1</source>
        <translation>Kugel %1 duplizieren</translation>
    </message>
</context>
<context>
    <name>forcelab::SimulationController</name>
    <message>
        <source>%1 pane: %2</source>
        <translation>Bereich %1: %2</translation>
    </message>
    <message>
        <source>your code</source>
        <translation>dein Code</translation>
    </message>
    <message>
        <source>spawn.count: %1 listed + %2 random balls is more than the limit of %3</source>
        <translation>spawn.count: %1 aufgeführte + %2 Zufallskugeln sind mehr als die Grenze von %3</translation>
    </message>
    <message>
        <source>time scale: %1 is outside %2 to %3</source>
        <translation>Zeitmaßstab: %1 liegt außerhalb von %2 bis %3</translation>
    </message>
    <message>
        <source>ghost: %1</source>
        <translation>Geist: %1</translation>
    </message>
</context>
<context>
    <name>forcelab::SpeedHistogram</name>
    <message>
        <source>Histogram of the balls&apos; speeds with the Maxwell–Boltzmann curve</source>
        <translation>Histogramm der Kugeltempos mit der Maxwell-Boltzmann-Kurve</translation>
    </message>
    <message>
        <source>balls</source>
        <translation>Kugeln</translation>
    </message>
    <message>
        <source>Maxwell–Boltzmann (2D), same energy</source>
        <translation>Maxwell-Boltzmann (2D), gleiche Energie</translation>
    </message>
    <message>
        <source>speed (px/s)</source>
        <translation>Tempo (px/s)</translation>
    </message>
    <message>
        <source>speed (%1)</source>
        <translation>Tempo (%1)</translation>
    </message>
    <message>
        <source>%1balls per %2 %3</source>
        <translation>%1Kugeln pro %2 %3</translation>
    </message>
    <message>
        <source>Speeds of %1</source>
        <translation>Tempos von %1</translation>
    </message>
    <message>
        <source>ball</source>
        <translation>Kugel</translation>
    </message>
</context>
<context>
    <name>forcelab::StageSliders</name>
    <message>
        <source>Left</source>
        <translation>Links</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Rechts</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Oben</translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation>Unten</translation>
    </message>
    <message>
        <source>A wall whose button is not pressed is open: a ball leaves through it</source>
        <translation>Eine Wand, deren Knopf nicht gedrückt ist, ist offen: Eine Kugel verlässt den Kasten durch sie</translation>
    </message>
    <message>
        <source>Off: a ball&apos;s centre may be anywhere in the box, so it can start partly outside a wall. Changing it places the balls again</source>
        <translation>Aus: Der Mittelpunkt einer Kugel darf überall im Kasten liegen, sie kann also teilweise außerhalb einer Wand starten. Eine Änderung platziert die Kugeln neu</translation>
    </message>
    <message>
        <source>Place balls fully inside</source>
        <translation>Kugeln ganz innen platzieren</translation>
    </message>
    <message>
        <source>Let balls start partly outside</source>
        <translation>Kugeln teilweise außen starten lassen</translation>
    </message>
    <message>
        <source>Slowest random ball</source>
        <translation>Langsamste Zufallskugel</translation>
    </message>
    <message>
        <source>Fastest random ball</source>
        <translation>Schnellste Zufallskugel</translation>
    </message>
    <message>
        <source>Walls: &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>Wände: &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Slowest random ball: &lt;b&gt;%1&lt;/b&gt; %2</source>
        <translation>Langsamste Zufallskugel: &lt;b&gt;%1&lt;/b&gt; %2</translation>
    </message>
    <message>
        <source>Fastest random ball: &lt;b&gt;%1&lt;/b&gt; %2</source>
        <translation>Schnellste Zufallskugel: &lt;b&gt;%1&lt;/b&gt; %2</translation>
    </message>
    <message>
        <source>Switch off</source>
        <translation>Ausschalten</translation>
    </message>
    <message>
        <source>Switch on</source>
        <translation>Einschalten</translation>
    </message>
    <message>
        <source>Start fully inside: &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>Ganz innen starten: &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <source>on</source>
        <translation>an</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
</context>
<context>
    <name>forcelab::StageToolTitle</name>
    <message>
        <source>Close (the tool&apos;s key again)</source>
        <translation>Schließen (erneut die Taste des Werkzeugs)</translation>
    </message>
</context>
<context>
    <name>forcelab::StageView</name>
    <message>
        <source>Sliders</source>
        <translation>Regler</translation>
    </message>
    <message>
        <source>Show the lesson&apos;s sliders under the box in the stage view (S)</source>
        <translation>Die Regler der Lektion in der Bühnenansicht unter dem Kasten zeigen (S)</translation>
    </message>
    <message>
        <source>Balls</source>
        <translation>Kugeln</translation>
    </message>
    <message>
        <source>Show every ball&apos;s numbers under the box, to type new ones (T)</source>
        <translation>Die Zahlen jeder Kugel unter dem Kasten zeigen, um neue einzugeben (T)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Stopped:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Angehalten:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>t = %1 s   %2× speed</source>
        <translation>t = %1 s   %2× Tempo</translation>
    </message>
</context>
<context>
    <name>forcelab::StepApartDock</name>
    <message>
        <source>One Step Apart</source>
        <translation>Ein Schritt zerlegt</translation>
    </message>
    <message>
        <source>all</source>
        <translation>alle</translation>
    </message>
    <message>
        <source>Sub-step shown</source>
        <translation>Gezeigter Teilschritt</translation>
    </message>
    <message>
        <source>Sub-step shown:</source>
        <translation>Gezeigter Teilschritt:</translation>
    </message>
    <message>
        <source>◀ Step back</source>
        <translation>◀ Schritt zurück</translation>
    </message>
    <message>
        <source>Step ▶</source>
        <translation>Schritt ▶</translation>
    </message>
    <message>
        <source>Pause to take a step apart: it is worked out for one step at a time, not for every frame.</source>
        <translation>Halte an, um einen Schritt zu zerlegen: Er wird jeweils für einen Schritt berechnet, nicht für jedes Bild.</translation>
    </message>
    <message>
        <source>There is no ball to follow.</source>
        <translation>Es gibt keine Kugel zum Verfolgen.</translation>
    </message>
    <message>
        <source>Sub-step %1 of %2: h = %3 s, starting at</source>
        <translation>Teilschritt %1 von %2: h = %3 s, beginnend bei</translation>
    </message>
    <message>
        <source>The step starts: h = %1 s</source>
        <translation>Der Schritt beginnt: h = %1 s</translation>
    </message>
    <message>
        <source>Force: %1 adds its acceleration</source>
        <translation>Kraft: %1 addiert ihre Beschleunigung</translation>
    </message>
    <message>
        <source>its own part: (%1, %2) px/s²</source>
        <translation>ihr eigener Anteil: (%1, %2) px/s²</translation>
    </message>
    <message>
        <source>Acceleration: all the forces added up</source>
        <translation>Beschleunigung: alle Kräfte zusammengezählt</translation>
    </message>
    <message>
        <source>Acceleration k%1, at a trial state (Runge-Kutta)</source>
        <translation>Beschleunigung k%1, in einem Probezustand (Runge-Kutta)</translation>
    </message>
    <message>
        <source>no force is switched on: the acceleration stays 0</source>
        <translation>keine Kraft ist eingeschaltet: Die Beschleunigung bleibt 0</translation>
    </message>
    <message>
        <source>Velocity changes</source>
        <translation>Geschwindigkeit ändert sich</translation>
    </message>
    <message>
        <source>Position moves</source>
        <translation>Position verschiebt sich</translation>
    </message>
    <message>
        <source>with the %1 accelerations above, weighted 1, 2, 2, 1</source>
        <translation>mit den %1 Beschleunigungen oben, gewichtet 1, 2, 2, 1</translation>
    </message>
    <message>
        <source>no wall touched: nothing changed</source>
        <translation>keine Wand berührt: nichts geändert</translation>
    </message>
    <message>
        <source>nothing changed for this ball</source>
        <translation>für diese Kugel hat sich nichts geändert</translation>
    </message>
    <message>
        <source>Detection: which balls touch?</source>
        <translation>Erkennung: Welche Kugeln berühren sich?</translation>
    </message>
    <message>
        <source>ball %1 and ball %2</source>
        <translation>Kugel %1 und Kugel %2</translation>
    </message>
    <message>
        <source>no ball touches ball %1 (%2 touching pairs in all)</source>
        <translation>keine Kugel berührt Kugel %1 (insgesamt %2 sich berührende Paare)</translation>
    </message>
    <message>
        <source>touching: %1</source>
        <translation>berührend: %1</translation>
    </message>
    <message>
        <source>Response with ball %1: the velocities change</source>
        <translation>Reaktion mit Kugel %1: Die Geschwindigkeiten ändern sich</translation>
    </message>
    <message>
        <source>they are moving apart already: no change</source>
        <translation>sie bewegen sich schon auseinander: keine Änderung</translation>
    </message>
    <message>
        <source>Δvx = %1 px/s, Δvy = %2 px/s</source>
        <translation>Δvx = %1 px/s, Δvy = %2 px/s</translation>
    </message>
    <message>
        <source>Push-apart from ball %1: out of each other</source>
        <translation>Auseinanderschieben von Kugel %1: aus einander heraus</translation>
    </message>
    <message>
        <source>overlap %1 px; Δx = %2 px, Δy = %3 px</source>
        <translation>Überlappung %1 px; Δx = %2 px, Δy = %3 px</translation>
    </message>
    <message>
        <source>Check: the script&apos;s step against the engine&apos;s (C++)</source>
        <translation>Prüfung: der Schritt des Skripts gegen den der Engine (C++)</translation>
    </message>
    <message>
        <source>matches the engine bit for bit</source>
        <translation>stimmt Bit für Bit mit der Engine überein</translation>
    </message>
    <message>
        <source>differs from the engine by Δx = %1, Δy = %2 px, Δvx = %3, Δvy = %4 px/s</source>
        <translation>weicht von der Engine ab um Δx = %1, Δy = %2 px, Δvx = %3, Δvy = %4 px/s</translation>
    </message>
    <message>
        <source>One step, taken apart</source>
        <translation>Ein Schritt, zerlegt</translation>
    </message>
    <message>
        <source>Ball %1, step %2 → %3, in the order the JavaScript runs it. Changed values are highlighted.</source>
        <translation>Kugel %1, Schritt %2 → %3, in der Reihenfolge, in der das JavaScript ihn ausführt. Geänderte Werte sind hervorgehoben.</translation>
    </message>
</context>
<context>
    <name>forcelab::StopwatchDock</name>
    <message>
        <source>Stopwatch</source>
        <translation>Stoppuhr</translation>
    </message>
    <message>
        <source>by hand</source>
        <translation>von Hand</translation>
    </message>
    <message>
        <source>on the event</source>
        <translation>beim Ereignis</translation>
    </message>
    <message>
        <source>Start the stopwatch</source>
        <translation>Stoppuhr starten</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>after events:</source>
        <translation>nach Ereignissen:</translation>
    </message>
    <message>
        <source>Stop the stopwatch</source>
        <translation>Stoppuhr anhalten</translation>
    </message>
    <message>
        <source>Events before the stopwatch stops</source>
        <translation>Ereignisse, bevor die Stoppuhr anhält</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>a bounce (moving down, then up)</source>
        <translation>ein Aufprall (erst nach unten, dann nach oben)</translation>
    </message>
    <message>
        <source>the top of a flight</source>
        <translation>der höchste Punkt eines Flugs</translation>
    </message>
    <message>
        <source>crossing the line x =</source>
        <translation>Überqueren der Linie x =</translation>
    </message>
    <message>
        <source>crossing the line y =</source>
        <translation>Überqueren der Linie y =</translation>
    </message>
    <message>
        <source>a full turn round the centre</source>
        <translation>eine volle Runde um den Mittelpunkt</translation>
    </message>
    <message>
        <source>Event</source>
        <translation>Ereignis</translation>
    </message>
    <message>
        <source>Line position</source>
        <translation>Position der Linie</translation>
    </message>
    <message>
        <source>Line at</source>
        <translation>Linie bei</translation>
    </message>
    <message>
        <source>Ball watched</source>
        <translation>Beobachtete Kugel</translation>
    </message>
    <message>
        <source>Ball</source>
        <translation>Kugel</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Arm</source>
        <translation>Scharf schalten</translation>
    </message>
    <message>
        <source>Waiting…</source>
        <translation>Warte …</translation>
    </message>
    <message>
        <source>Start again</source>
        <translation>Neu starten</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Last times: %1</source>
        <translation>Letzte Zeiten: %1</translation>
    </message>
</context>
<context>
    <name>forcelab::StudentCodeDock</name>
    <message>
        <source>Your Code</source>
        <translation>Dein Code</translation>
    </message>
    <message>
        <source>Rewrite:</source>
        <translation>Neu schreiben:</translation>
    </message>
    <message>
        <source>JavaScript file to rewrite</source>
        <translation>JavaScript-Datei zum Neuschreiben</translation>
    </message>
    <message>
        <source>The stage&apos;s code, one file per rule. Pick one and write your own version.</source>
        <translation>Der Code der Stufe, eine Datei pro Regel. Wähle eine aus und schreibe deine eigene Version.</translation>
    </message>
    <message>
        <source>Your JavaScript</source>
        <translation>Dein JavaScript</translation>
    </message>
    <message>
        <source>Run beside the reference</source>
        <translation>Neben der Referenz ausführen</translation>
    </message>
    <message>
        <source>Runs your version in place of the course&apos;s, beside the reference (Ctrl+Return)</source>
        <translation>Führt deine Version anstelle der des Kurses aus, neben der Referenz (Ctrl+Return)</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>Takes your code off the canvas</source>
        <translation>Nimmt deinen Code von der Zeichenfläche</translation>
    </message>
    <message>
        <source>Back to the course&apos;s file</source>
        <translation>Zurück zur Datei des Kurses</translation>
    </message>
    <message>
        <source>Throws away your changes to this file</source>
        <translation>Verwirft deine Änderungen an dieser Datei</translation>
    </message>
    <message>
        <source>%1 (yours)</source>
        <translation>%1 (deine)</translation>
    </message>
    <message>
        <source>Change the code above, then press Run: your version runs beside the course&apos;s.</source>
        <translation>Ändere den Code oben und drücke dann „Neben der Referenz ausführen“: Deine Version läuft neben der des Kurses.</translation>
    </message>
    <message>
        <source>Your changes: %1. Press Run to see them beside the reference.</source>
        <translation>Deine Änderungen: %1. Drücke „Neben der Referenz ausführen“, um sie neben der Referenz zu sehen.</translation>
    </message>
    <message>
        <source>Your code stopped. %1</source>
        <translation>Dein Code wurde angehalten. %1</translation>
    </message>
    <message>
        <source>Departs at step %1: your code has %2 balls, the reference %3.</source>
        <translation>Weicht ab bei Schritt %1: Dein Code hat %2 Kugeln, die Referenz %3.</translation>
    </message>
    <message>
        <source>Departs at step %1 (t = %2 s), ball %3: %4 is %5 in your code and %6 in the reference, %7 apart. Now the balls are up to %8 apart.</source>
        <translation>Weicht ab bei Schritt %1 (t = %2 s), Kugel %3: %4 ist %5 in deinem Code und %6 in der Referenz, %7 Unterschied. Jetzt liegen die Kugeln bis zu %8 auseinander.</translation>
    </message>
    <message>
        <source>Agrees with the reference for all %1 steps so far (x, y, vx and vy to 9 significant digits).</source>
        <translation>Stimmt bisher in allen %1 Schritten mit der Referenz überein (x, y, vx und vy auf 9 signifikante Stellen).</translation>
    </message>
</context>
<context>
    <name>forcelab::TimelineBar</name>
    <message>
        <source>Step back: pause and show the world one step dt earlier</source>
        <translation>Schritt zurück: anhalten und die Welt einen Schritt dt früher zeigen</translation>
    </message>
    <message>
        <source>Step: re-run the next recorded step, or take a new one at the latest</source>
        <translation>Schritt: den nächsten aufgezeichneten Schritt erneut ausführen oder am Ende einen neuen machen</translation>
    </message>
    <message>
        <source>The recorded past: drag to see the world at any step of it</source>
        <translation>Die aufgezeichnete Vergangenheit: ziehen, um die Welt bei jedem ihrer Schritte zu sehen</translation>
    </message>
    <message>
        <source>Step back</source>
        <translation>Schritt zurück</translation>
    </message>
    <message>
        <source>Step forward</source>
        <translation>Schritt vor</translation>
    </message>
    <message>
        <source>Timeline: the recorded steps</source>
        <translation>Zeitleiste: die aufgezeichneten Schritte</translation>
    </message>
    <message>
        <source>Time shown, of the time recorded</source>
        <translation>Gezeigte Zeit von der aufgezeichneten Zeit</translation>
    </message>
    <message>
        <source>t = %1 s of %2 s</source>
        <translation>t = %1 s von %2 s</translation>
    </message>
</context>
<context>
    <name>forcelab::TraceCheck</name>
    <message>
        <source>Check a Student&apos;s &amp;Trace…</source>
        <translation>Schülerprotokoll &amp;prüfen …</translation>
    </message>
    <message>
        <source>Check a trace a student&apos;s own program wrote (CSV or JSON: step, ball, x, y, vx, vy) against this run: where it first departs, and why</source>
        <translation>Ein Protokoll, das das eigene Programm eines Schülers geschrieben hat (CSV oder JSON: step, ball, x, y, vx, vy), mit diesem Lauf vergleichen: wo es zuerst abweicht und warum</translation>
    </message>
    <message>
        <source>Check a Student&apos;s Trace</source>
        <translation>Schülerprotokoll prüfen</translation>
    </message>
    <message>
        <source>Traces (*.csv *.json);;All files (*)</source>
        <translation>Protokolle (*.csv *.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>%1: a trace is still being checked; wait for its result</source>
        <translation>%1: Ein Protokoll wird noch geprüft; warte auf sein Ergebnis</translation>
    </message>
    <message>
        <source>%1 cannot be checked: %2</source>
        <translation>%1 kann nicht geprüft werden: %2</translation>
    </message>
    <message>
        <source>%1 agrees with the run at every one of its %2 rows (to step %3, t = %4 s): the largest difference is %5.</source>
        <translation>%1 stimmt in jeder seiner %2 Zeilen mit dem Lauf überein (bis Schritt %3, t = %4 s): Die größte Abweichung ist %5.</translation>
    </message>
    <message>
        <source>%1 departs from the run at step %2 (t = %3 s), ball %4: %5 is %6 where the run has %7, off by %8.</source>
        <translation>%1 weicht bei Schritt %2 (t = %3 s) vom Lauf ab, Kugel %4: %5 ist %6, wo der Lauf %7 hat, Abweichung %8.</translation>
    </message>
    <message>
        <source>Likely cause: %1. The numbers follow the run with %2: %3</source>
        <translation>Wahrscheinliche Ursache: %1. Die Zahlen folgen dem Lauf mit %2: %3</translation>
    </message>
    <message>
        <source>No known mistake explains it: %1</source>
        <translation>Kein bekannter Fehler erklärt es: %1</translation>
    </message>
    <message>
        <source>The canvas does not go there: step %1 is past the %2 steps it runs to at once.</source>
        <translation>Die Zeichenfläche geht nicht dorthin: Schritt %1 liegt hinter den %2 Schritten, die sie auf einmal läuft.</translation>
    </message>
    <message>
        <source>Student&apos;s trace</source>
        <translation>Schülerprotokoll</translation>
    </message>
    <message>
        <source>student&apos;s ball %1, step %2</source>
        <translation>Kugel %1 des Schülers, Schritt %2</translation>
    </message>
</context>
</TS>
