<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es">
<context>
    <name>BallClipboard</name>
    <message>
        <source>the clipboard holds %1 characters, more than a ball&apos;s %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the clipboard does not hold a ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has an unknown field &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has no number &quot;%1&quot;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has &quot;pinned&quot; that is not true or false</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has a restitution that is not a number from 0 to 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has no valid colour</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>Colour</name>
    <message>
        <source>sky blue</source>
        <translation>azul cielo</translation>
    </message>
    <message>
        <source>blue</source>
        <translation>azul</translation>
    </message>
    <message>
        <source>red</source>
        <translation>rojo</translation>
    </message>
    <message>
        <source>orange</source>
        <translation>naranja</translation>
    </message>
    <message>
        <source>yellow</source>
        <translation>amarillo</translation>
    </message>
    <message>
        <source>green</source>
        <translation>verde</translation>
    </message>
    <message>
        <source>purple</source>
        <translation>morado</translation>
    </message>
    <message>
        <source>pink</source>
        <translation>rosa</translation>
    </message>
    <message>
        <source>black</source>
        <translation>negro</translation>
    </message>
    <message>
        <source>grey</source>
        <translation>gris</translation>
    </message>
    <message>
        <source>white</source>
        <translation>blanco</translation>
    </message>
</context>
<context>
    <name>CommandLine</name>
    <message>
        <source>A workbench for forces and collisions of 2D balls.</source>
        <translation>Un banco de trabajo de fuerzas y choques de bolas en 2D.</translation>
    </message>
    <message>
        <source>Lesson file or built-in lesson id.</source>
        <translation>Archivo de lección o identificador de una lección incluida.</translation>
    </message>
    <message>
        <source>Save a picture of the window to FILE and quit.</source>
        <translation>Guardar una imagen de la ventana en FILE y salir.</translation>
    </message>
    <message>
        <source>Seconds to run in real time before --screenshot (default 3).</source>
        <translation>Segundos de ejecución en tiempo real antes de --screenshot (por defecto 3).</translation>
    </message>
    <message>
        <source>For --screenshot: step the lesson to simulated time T (seconds) and take the picture there, paused, instead of --after.</source>
        <translation>Para --screenshot: avanzar la lección hasta el tiempo simulado T (segundos) y tomar la imagen allí, en pausa, en lugar de --after.</translation>
    </message>
    <message>
        <source>For --screenshot: the window&apos;s size in pixels (default: the screen).</source>
        <translation>Para --screenshot: el tamaño de la ventana en píxeles (por defecto: la pantalla).</translation>
    </message>
    <message>
        <source>Open in the stage view for a projector (F11; Escape leaves).</source>
        <translation>Abrir en la vista de escenario para un proyector (F11; Escape sale).</translation>
    </message>
    <message>
        <source>Time drawing 1k, 10k and 50k balls offscreen and quit.</source>
        <translation>Medir el dibujo de 1k, 10k y 50k bolas fuera de pantalla y salir.</translation>
    </message>
    <message>
        <source>Select ball N at the start (the Inspector shows its numbers).</source>
        <translation>Seleccionar la bola N al empezar (el Inspector muestra sus valores).</translation>
    </message>
    <message>
        <source>Show the table of the balls (the Balls dock, or under the box with --present), with the selected ball.</source>
        <translation>Mostrar la tabla de las bolas (el panel Bolas, o bajo la caja con --present), con la bola seleccionada.</translation>
    </message>
    <message>
        <source>Zoom in Z times on the selected ball (or the box&apos;s middle).</source>
        <translation>Acercar Z veces la bola seleccionada (o el centro de la caja).</translation>
    </message>
    <message>
        <source>Follow the selected ball (with --select).</source>
        <translation>Seguir la bola seleccionada (con --select).</translation>
    </message>
    <message>
        <source>Zoom so every ball is seen (with --time: where they are then).</source>
        <translation>Ajustar el zoom para ver todas las bolas (con --time: donde estén entonces).</translation>
    </message>
    <message>
        <source>Show the program in language CODE (en, de or es) this time, without changing the remembered one (View &gt; Language).</source>
        <translation>Mostrar el programa esta vez en el idioma CODE (en, de o es), sin cambiar el recordado (Ver &gt; Idioma).</translation>
    </message>
</context>
<context>
    <name>ForceModel</name>
    <message>
        <source>gravity</source>
        <translation>gravedad</translation>
    </message>
    <message>
        <source>drag</source>
        <translation>rozamiento</translation>
    </message>
    <message>
        <source>wind</source>
        <translation>viento</translation>
    </message>
    <message>
        <source>random</source>
        <translation>aleatoria</translation>
    </message>
    <message>
        <source>point force</source>
        <translation>fuerza de un punto</translation>
    </message>
    <message>
        <source>pointer</source>
        <translation>puntero</translation>
    </message>
    <message>
        <source>spring</source>
        <translation>muelle</translation>
    </message>
    <message>
        <source>homing</source>
        <translation>regreso a casa</translation>
    </message>
    <message>
        <source>between balls</source>
        <translation>entre bolas</translation>
    </message>
    <message>
        <source>magnetic</source>
        <translation>magnética</translation>
    </message>
    <message>
        <source>custom force</source>
        <translation>fuerza propia</translation>
    </message>
</context>
<context>
    <name>Language</name>
    <message>
        <source>English</source>
        <translation>inglés</translation>
    </message>
    <message>
        <source>German</source>
        <translation>alemán</translation>
    </message>
    <message>
        <source>Spanish</source>
        <translation>español</translation>
    </message>
    <message>
        <source>This lesson is not written in your language yet: its text is shown in %1.</source>
        <translation>Esta lección aún no está escrita en tu idioma: su texto se muestra en %1.</translation>
    </message>
</context>
<context>
    <name>Overlay</name>
    <message>
        <source>velocity</source>
        <translation>velocidad</translation>
    </message>
    <message>
        <source>acceleration</source>
        <translation>aceleración</translation>
    </message>
    <message>
        <source>force</source>
        <translation>fuerza</translation>
    </message>
    <message>
        <source>line of impact</source>
        <translation>línea de impacto</translation>
    </message>
    <message>
        <source>tangent</source>
        <translation>tangente</translation>
    </message>
    <message>
        <source>momenta  p = m v</source>
        <translation>momentos  p = m v</translation>
    </message>
    <message>
        <source>forces by source</source>
        <translation>fuerzas por origen</translation>
    </message>
</context>
<context>
    <name>Parameter</name>
    <message>
        <source>Box width</source>
        <translation>Ancho de la caja</translation>
    </message>
    <message>
        <source>Box height</source>
        <translation>Alto de la caja</translation>
    </message>
    <message>
        <source>Wall model</source>
        <translation>Modelo de pared</translation>
    </message>
    <message>
        <source>Wall restitution</source>
        <translation>Restitución de las paredes</translation>
    </message>
    <message>
        <source>Middle wall</source>
        <translation>Pared central</translation>
    </message>
    <message>
        <source>Test the centre only</source>
        <translation>Comprobar solo el centro</translation>
    </message>
    <message>
        <source>Left wall</source>
        <translation>Pared izquierda</translation>
    </message>
    <message>
        <source>Right wall</source>
        <translation>Pared derecha</translation>
    </message>
    <message>
        <source>Top wall</source>
        <translation>Pared superior</translation>
    </message>
    <message>
        <source>Floor</source>
        <translation>Suelo</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrador</translation>
    </message>
    <message>
        <source>Step dt</source>
        <translation>Paso dt</translation>
    </message>
    <message>
        <source>Sub-steps</source>
        <translation>Subpasos</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerancia</translation>
    </message>
    <message>
        <source>Move per frame</source>
        <translation>Mover por fotograma</translation>
    </message>
    <message>
        <source>Step past close passes</source>
        <translation>Pasar de largo los acercamientos</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Gravedad</translation>
    </message>
    <message>
        <source>g x (right)</source>
        <translation>g x (derecha)</translation>
    </message>
    <message>
        <source>g y (down)</source>
        <translation>g y (abajo)</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Rozamiento del aire</translation>
    </message>
    <message>
        <source>Drag law</source>
        <translation>Ley del rozamiento</translation>
    </message>
    <message>
        <source>Drag k</source>
        <translation>Rozamiento k</translation>
    </message>
    <message>
        <source>Drag scaling</source>
        <translation>Rozamiento según</translation>
    </message>
    <message>
        <source>Wind</source>
        <translation>Viento</translation>
    </message>
    <message>
        <source>Wind strength</source>
        <translation>Fuerza del viento</translation>
    </message>
    <message>
        <source>Wind scaling</source>
        <translation>Viento según</translation>
    </message>
    <message>
        <source>Smoothed step</source>
        <translation>Paso suavizado</translation>
    </message>
    <message>
        <source>Noise frequency</source>
        <translation>Frecuencia del ruido</translation>
    </message>
    <message>
        <source>Compare with</source>
        <translation>Comparar con</translation>
    </message>
    <message>
        <source>Random acceleration</source>
        <translation>Aceleración aleatoria</translation>
    </message>
    <message>
        <source>One value per ball</source>
        <translation>Un valor por bola</translation>
    </message>
    <message>
        <source>Random strength</source>
        <translation>Intensidad aleatoria</translation>
    </message>
    <message>
        <source>Un-centred (0 to strength)</source>
        <translation>Sin centrar (de 0 a la intensidad)</translation>
    </message>
    <message>
        <source>Point force</source>
        <translation>Fuerza de un punto</translation>
    </message>
    <message>
        <source>Point kind</source>
        <translation>Tipo de punto</translation>
    </message>
    <message>
        <source>Point x</source>
        <translation>Punto x</translation>
    </message>
    <message>
        <source>Point y</source>
        <translation>Punto y</translation>
    </message>
    <message>
        <source>Point strength</source>
        <translation>Intensidad del punto</translation>
    </message>
    <message>
        <source>Point clamp (0 = off)</source>
        <translation>Tope del punto (0 = sin tope)</translation>
    </message>
    <message>
        <source>Point scaling</source>
        <translation>Punto según</translation>
    </message>
    <message>
        <source>Un-normalised (S d / d²)</source>
        <translation>Sin normalizar (S d / d²)</translation>
    </message>
    <message>
        <source>Spring</source>
        <translation>Muelle</translation>
    </message>
    <message>
        <source>Anchor x</source>
        <translation>Anclaje x</translation>
    </message>
    <message>
        <source>Anchor y</source>
        <translation>Anclaje y</translation>
    </message>
    <message>
        <source>Spring k</source>
        <translation>Muelle k</translation>
    </message>
    <message>
        <source>Gravity between balls</source>
        <translation>Gravedad entre bolas</translation>
    </message>
    <message>
        <source>G</source>
        <translation>G</translation>
    </message>
    <message>
        <source>Softening ε</source>
        <translation>Suavizado ε</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Regreso a casa</translation>
    </message>
    <message>
        <source>Homing strength</source>
        <translation>Fuerza de regreso</translation>
    </message>
    <message>
        <source>Pointer force</source>
        <translation>Fuerza del puntero</translation>
    </message>
    <message>
        <source>Pointer strength</source>
        <translation>Intensidad del puntero</translation>
    </message>
    <message>
        <source>Pointer clamp (0 = off)</source>
        <translation>Tope del puntero (0 = sin tope)</translation>
    </message>
    <message>
        <source>Magnetic field</source>
        <translation>Campo magnético</translation>
    </message>
    <message>
        <source>Field B</source>
        <translation>Campo B</translation>
    </message>
    <message>
        <source>Custom force</source>
        <translation>Fuerza propia</translation>
    </message>
    <message>
        <source>Formulas give a, not F</source>
        <translation>Las fórmulas dan a, no F</translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation>Límite de rapidez</translation>
    </message>
    <message>
        <source>Largest speed</source>
        <translation>Rapidez máxima</translation>
    </message>
    <message>
        <source>Detection</source>
        <translation>Detección</translation>
    </message>
    <message>
        <source>Response</source>
        <translation>Respuesta</translation>
    </message>
    <message>
        <source>Ball restitution</source>
        <translation>Restitución de las bolas</translation>
    </message>
    <message>
        <source>Continuous</source>
        <translation>Continua</translation>
    </message>
    <message>
        <source>Resting contacts</source>
        <translation>Contactos en reposo</translation>
    </message>
</context>
<context>
    <name>ParameterHelp</name>
    <message>
        <source>Width of the box the balls live in.</source>
        <translation>Ancho de la caja en la que viven las bolas.</translation>
    </message>
    <message>
        <source>Height of the box; y points down.</source>
        <translation>Alto de la caja; y apunta hacia abajo.</translation>
    </message>
    <message>
        <source>How a ball that crossed a wall is put back: clamp, mirror, exact (time of impact) or reverse.</source>
        <translation>Cómo se devuelve una bola que ha cruzado una pared: clamp, mirror, exact (instante del choque) o reverse.</translation>
    </message>
    <message>
        <source>Share of the speed into a wall that a bounce keeps: 1 loses nothing, 0 stops the ball.</source>
        <translation>Parte de la rapidez contra la pared que conserva un rebote: 1 no pierde nada, 0 detiene la bola.</translation>
    </message>
    <message>
        <source>A wall down the middle of the box; each ball stays on its side.</source>
        <translation>Una pared en el centro de la caja; cada bola se queda en su lado.</translation>
    </message>
    <message>
        <source>The wall test uses the ball&apos;s centre instead of its edge (stage 3&apos;s bug).</source>
        <translation>La prueba de la pared usa el centro de la bola en lugar de su borde (el error de la etapa 3).</translation>
    </message>
    <message>
        <source>A wall at x = 0 (in lesson files: &quot;left&quot; in the walls list).</source>
        <translation>Una pared en x = 0 (en los archivos de lección: &quot;left&quot; en la lista walls).</translation>
    </message>
    <message>
        <source>A wall at x = width.</source>
        <translation>Una pared en x = ancho.</translation>
    </message>
    <message>
        <source>A wall at y = 0.</source>
        <translation>Una pared en y = 0.</translation>
    </message>
    <message>
        <source>A wall at y = height.</source>
        <translation>Una pared en y = alto.</translation>
    </message>
    <message>
        <source>The method that moves the balls through one step.</source>
        <translation>El método que mueve las bolas durante un paso.</translation>
    </message>
    <message>
        <source>Simulated time of one step.</source>
        <translation>Tiempo simulado de un paso.</translation>
    </message>
    <message>
        <source>Each step is split into this many equal sub-steps.</source>
        <translation>Cada paso se divide en tantos subpasos iguales.</translation>
    </message>
    <message>
        <source>Error allowed per sub-step by the adaptive integrators (rk45, ias15); ias15 works to the rounding floor where this asks for less.</source>
        <translation>Error permitido por subpaso en los integradores adaptativos (rk45, ias15); ias15 llega al límite del redondeo cuando aquí se pide menos.</translation>
    </message>
    <message>
        <source>Ignore dt: every step moves the balls as if 1/60 s had passed (stage 5&apos;s bug).</source>
        <translation>Ignorar dt: cada paso mueve las bolas como si hubiera pasado 1/60 s (el error de la etapa 5).</translation>
    </message>
    <message>
        <source>Let a fixed step jump past a close pass it cannot follow instead of stopping there (stage 17&apos;s slingshot bug).</source>
        <translation>Dejar que un paso fijo salte un acercamiento que no puede seguir en lugar de detenerse allí (el error de la honda de la etapa 17).</translation>
    </message>
    <message>
        <source>The same downward pull on every ball.</source>
        <translation>La misma atracción hacia abajo sobre cada bola.</translation>
    </message>
    <message>
        <source>Sideways part of gravity.</source>
        <translation>Parte lateral de la gravedad.</translation>
    </message>
    <message>
        <source>Downward part of gravity; 980 px/s² is Earth&apos;s if 1 px is 1 cm.</source>
        <translation>Parte de la gravedad hacia abajo; 980 px/s² es la de la Tierra si 1 px es 1 cm.</translation>
    </message>
    <message>
        <source>A force against the velocity.</source>
        <translation>Una fuerza contra la velocidad.</translation>
    </message>
    <message>
        <source>linear: F ∝ −v; quadratic: F ∝ −|v| v.</source>
        <translation>linear: F ∝ −v; quadratic: F ∝ −|v| v.</translation>
    </message>
    <message>
        <source>How strong the drag is: how fast a 10 px ball slows down.</source>
        <translation>Cuánto frena el rozamiento: lo rápido que se frena una bola de 10 px.</translation>
    </message>
    <message>
        <source>mass: drag is a force, F = −k m(10 px) v, so a heavy ball slows down less and falls faster; none: the tutorial&apos;s model, every ball loses the same share of its speed; radius: air drag on spheres, × 10 px / r.</source>
        <translation>mass: el rozamiento es una fuerza, F = −k m(10 px) v, así que una bola pesada se frena menos y cae más rápido; none: el modelo del curso, cada bola pierde la misma parte de su rapidez; radius: rozamiento del aire sobre esferas, × 10 px / r.</translation>
    </message>
    <message>
        <source>off, random (a new gust every step), smoothed (a bounded random walk), noise (smooth noise) or pointer (blown by the mouse).</source>
        <translation>off, random (una ráfaga nueva en cada paso), smoothed (un paseo aleatorio acotado), noise (ruido suave) o pointer (soplado por el ratón).</translation>
    </message>
    <message>
        <source>Largest sideways push on a 10 px ball.</source>
        <translation>Mayor empuje lateral sobre una bola de 10 px.</translation>
    </message>
    <message>
        <source>none: every ball is pushed alike; radius: by 10 px / r; mass: as a force, by m(10 px) / m.</source>
        <translation>none: todas las bolas reciben el mismo empuje; radius: por 10 px / r; mass: como una fuerza, por m(10 px) / m.</translation>
    </message>
    <message>
        <source>Largest change of the smoothed wind per step, as a share of its strength.</source>
        <translation>Mayor cambio del viento suavizado por paso, como parte de su intensidad.</translation>
    </message>
    <message>
        <source>How fast the noise wind changes.</source>
        <translation>Lo rápido que cambia el viento de ruido.</translation>
    </message>
    <message>
        <source>A second wind computed beside the first for a second vane; it pushes nothing.</source>
        <translation>Un segundo viento calculado junto al primero para una segunda veleta; no empuja nada.</translation>
    </message>
    <message>
        <source>A random push on every ball, centred on zero (stage 10).</source>
        <translation>Un empujón aleatorio sobre cada bola, centrado en cero (etapa 10).</translation>
    </message>
    <message>
        <source>Off: a new random value every step. On: each ball keeps the value it drew first.</source>
        <translation>Desactivado: un valor aleatorio nuevo en cada paso. Activado: cada bola conserva el valor que sacó la primera vez.</translation>
    </message>
    <message>
        <source>Largest value of each component.</source>
        <translation>Mayor valor de cada componente.</translation>
    </message>
    <message>
        <source>The course&apos;s Math.random() bug: each component is drawn in [0, strength) instead of [−strength, strength), so every ball drifts right and down at strength/2 on average.</source>
        <translation>El error de Math.random() del curso: cada componente se saca de [0, intensidad) en lugar de [−intensidad, intensidad), así que cada bola deriva de media hacia la derecha y hacia abajo a intensidad/2.</translation>
    </message>
    <message>
        <source>An inverse-square pull or push from a fixed point.</source>
        <translation>Una atracción o repulsión desde un punto fijo, inversa al cuadrado de la distancia.</translation>
    </message>
    <message>
        <source>attract or repel.</source>
        <translation>attract o repel.</translation>
    </message>
    <message>
        <source>Where the point is, across.</source>
        <translation>Dónde está el punto, en horizontal.</translation>
    </message>
    <message>
        <source>Where the point is, down.</source>
        <translation>Dónde está el punto, en vertical.</translation>
    </message>
    <message>
        <source>S in a = S / d² for a 10 px ball.</source>
        <translation>S en a = S / d² para una bola de 10 px.</translation>
    </message>
    <message>
        <source>The point&apos;s pull is never more than this near it.</source>
        <translation>La atracción del punto nunca supera este valor cerca de él.</translation>
    </message>
    <message>
        <source>none, radius or mass, as for the wind.</source>
        <translation>none, radius o mass, como en el viento.</translation>
    </message>
    <message>
        <source>The course&apos;s repulsion bug: the difference vector d times S / d² instead of its unit vector, so |a| = S / d, a 1/d law, not S / d².</source>
        <translation>El error de la repulsión del curso: el vector diferencia d por S / d² en lugar de su vector unitario, así que |a| = S / d, una ley 1/d y no S / d².</translation>
    </message>
    <message>
        <source>Every ball tied to one anchor by a spring (Hooke&apos;s law).</source>
        <translation>Cada bola está atada a un anclaje por un muelle (ley de Hooke).</translation>
    </message>
    <message>
        <source>Where the springs are tied, across.</source>
        <translation>Dónde están atados los muelles, en horizontal.</translation>
    </message>
    <message>
        <source>Where the springs are tied, down.</source>
        <translation>Dónde están atados los muelles, en vertical.</translation>
    </message>
    <message>
        <source>Stiffness per unit mass: a = −k (x − anchor), so ω = √k.</source>
        <translation>Rigidez por unidad de masa: a = −k (x − anclaje), así que ω = √k.</translation>
    </message>
    <message>
        <source>Every pair of balls pulls together (or pushes apart for G &lt; 0).</source>
        <translation>Cada par de bolas se atrae (o se repele si G &lt; 0).</translation>
    </message>
    <message>
        <source>The constant in F = G m₁ m₂ / r².</source>
        <translation>La constante de F = G m₁ m₂ / r².</translation>
    </message>
    <message>
        <source>ε in F = G m₁ m₂ r / (r² + ε²)^(3/2): the pull fades smoothly to zero inside ε.</source>
        <translation>ε en F = G m₁ m₂ r / (r² + ε²)^(3/2): dentro de ε la atracción se desvanece suavemente hasta cero.</translation>
    </message>
    <message>
        <source>Each ball tied by a spring to the home of its colour.</source>
        <translation>Cada bola está atada por un muelle a la casa de su color.</translation>
    </message>
    <message>
        <source>Stiffness of the spring to home, per unit mass.</source>
        <translation>Rigidez del muelle hacia casa, por unidad de masa.</translation>
    </message>
    <message>
        <source>The mouse pointer pulls (hover) or pushes (pressed).</source>
        <translation>El puntero del ratón atrae (al pasar por encima) o empuja (pulsado).</translation>
    </message>
    <message>
        <source>S in a = S / d².</source>
        <translation>S en a = S / d².</translation>
    </message>
    <message>
        <source>The pointer&apos;s pull is never more than this.</source>
        <translation>La atracción del puntero nunca supera este valor.</translation>
    </message>
    <message>
        <source>A field out of the screen that turns every moving charge, F = q v × B, without changing its speed.</source>
        <translation>Un campo que sale de la pantalla y desvía cada carga en movimiento, F = q v × B, sin cambiar su rapidez.</translation>
    </message>
    <message>
        <source>How fast a 10 px ball of charge 1 turns: ω = q B m(10 px) / m; negative turns the other way.</source>
        <translation>Lo rápido que gira una bola de 10 px con carga 1: ω = q B m(10 px) / m; un valor negativo gira al revés.</translation>
    </message>
    <message>
        <source>A force law written as formulas of x, y, vx, vy, m, r, q, t, W, H and named constants (the Force editor).</source>
        <translation>Una ley de fuerza escrita como fórmulas de x, y, vx, vy, m, r, q, t, W, H y constantes con nombre (el editor de fuerzas).</translation>
    </message>
    <message>
        <source>On: the formulas are the acceleration (px/s²), the same for every mass; off: the force, divided by m.</source>
        <translation>Activado: las fórmulas son la aceleración (px/s²), igual para cualquier masa; desactivado: la fuerza, dividida por m.</translation>
    </message>
    <message>
        <source>No ball moves faster than the limit (a stand-in for terminal velocity).</source>
        <translation>Ninguna bola va más rápido que el límite (un sustituto de la velocidad límite).</translation>
    </message>
    <message>
        <source>The limit.</source>
        <translation>El límite.</translation>
    </message>
    <message>
        <source>How touching pairs are found: brute, halved, sweep or grid.</source>
        <translation>Cómo se encuentran los pares que se tocan: brute, halved, sweep o grid.</translation>
    </message>
    <message>
        <source>What a touching pair does: none, flag, 1d-reverse, 1d-elastic, 2d-axis or 2d-impulse.</source>
        <translation>Qué hace un par que se toca: none, flag, 1d-reverse, 1d-elastic, 2d-axis o 2d-impulse.</translation>
    </message>
    <message>
        <source>Share of the approach speed a collision gives back.</source>
        <translation>Parte de la rapidez de acercamiento que devuelve un choque.</translation>
    </message>
    <message>
        <source>Find the moment of impact inside the step.</source>
        <translation>Encontrar el instante del choque dentro del paso.</translation>
    </message>
    <message>
        <source>Under gravity, solve a pile&apos;s contacts several times per step so it stands.</source>
        <translation>Con gravedad, resolver los contactos de una pila varias veces por paso para que se sostenga.</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Change speed to %1×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Walls: is the ball outside the box?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rule %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Goal:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>about %1 minutes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Expected answers</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Common misconceptions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What the scene is checked to show</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ForceLab: teacher&apos;s handbook</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>One section per lesson: the goal, the time it takes, the text students read, the challenges with their expected answers, the misconceptions to expect, and what the scene is checked to show (forcelab-cli check).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Showcase</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stage %1 of 29</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Beyond the course</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Challenges</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>For the teacher</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>SceneDescription</name>
    <message>
        <source>right</source>
        <translation>hacia la derecha</translation>
    </message>
    <message>
        <source>up and to the right</source>
        <translation>hacia arriba a la derecha</translation>
    </message>
    <message>
        <source>up</source>
        <translation>hacia arriba</translation>
    </message>
    <message>
        <source>up and to the left</source>
        <translation>hacia arriba a la izquierda</translation>
    </message>
    <message>
        <source>left</source>
        <translation>hacia la izquierda</translation>
    </message>
    <message>
        <source>down and to the left</source>
        <translation>hacia abajo a la izquierda</translation>
    </message>
    <message>
        <source>down</source>
        <translation>hacia abajo</translation>
    </message>
    <message>
        <source>down and to the right</source>
        <translation>hacia abajo a la derecha</translation>
    </message>
    <message>
        <source>the left wall</source>
        <translation>la pared izquierda</translation>
    </message>
    <message>
        <source>the right wall</source>
        <translation>la pared derecha</translation>
    </message>
    <message>
        <source>the ceiling</source>
        <translation>el techo</translation>
    </message>
    <message>
        <source>the floor</source>
        <translation>el suelo</translation>
    </message>
    <message>
        <source>the middle wall</source>
        <translation>la pared central</translation>
    </message>
    <message>
        <source>No balls.</source>
        <translation>Ninguna bola.</translation>
    </message>
    <message>
        <source>One ball.</source>
        <translation>Una bola.</translation>
    </message>
    <message>
        <source>%1 balls.</source>
        <translation>%1 bolas.</translation>
    </message>
    <message>
        <source>Ball %1</source>
        <translation>La bola %1</translation>
    </message>
    <message>
        <source>Ball %1 (%2)</source>
        <translation>La bola %1 (%2)</translation>
    </message>
    <message>
        <source>%1 is pinned in place.</source>
        <translation>%1 está fijada en su sitio.</translation>
    </message>
    <message>
        <source>%1 is at rest.</source>
        <translation>%1 está en reposo.</translation>
    </message>
    <message>
        <source>%1 moves %2 at %3</source>
        <translation>%1 se mueve %2 a %3</translation>
    </message>
    <message>
        <source>will hit %1 in %2 s</source>
        <translation>chocará con %1 en %2 s</translation>
    </message>
    <message>
        <source>will hit %1 in about %2 s</source>
        <translation>chocará con %1 en unos %2 s</translation>
    </message>
    <message>
        <source>and %1.</source>
        <translation>y %1.</translation>
    </message>
    <message>
        <source>It %1.</source>
        <translation>Después %1.</translation>
    </message>
    <message>
        <source>Total energy %1.</source>
        <translation>Energía total %1.</translation>
    </message>
</context>
<context>
    <name>WorldPainter</name>
    <message>
        <source>ball %1</source>
        <translation>bola %1</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>rapidez</translation>
    </message>
    <message>
        <source>position</source>
        <translation>posición</translation>
    </message>
    <message>
        <source>velocity</source>
        <translation>velocidad</translation>
    </message>
    <message>
        <source>accel.</source>
        <translation>acel.</translation>
    </message>
    <message>
        <source>kinetic</source>
        <translation>cinética</translation>
    </message>
    <message>
        <source>potential</source>
        <translation>potencial</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source>energy in %1: %2 %3</source>
        <translation>energía en %1: %2 %3</translation>
    </message>
    <message>
        <source>momentum (%1, %2) %3</source>
        <translation>momento (%1, %2) %3</translation>
    </message>
    <message>
        <source>energy in %1</source>
        <translation>energía en %1</translation>
    </message>
    <message>
        <source>momentum in %1</source>
        <translation>momento en %1</translation>
    </message>
    <message>
        <source>energy (%1)</source>
        <translation>energía (%1)</translation>
    </message>
    <message>
        <source>momentum (%1)</source>
        <translation>momento (%1)</translation>
    </message>
</context>
<context>
    <name>forcelab::AccuracyDock</name>
    <message>
        <source>Accuracy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drift</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ghost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Trade-off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Compare with another integrator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sensitivity twin (moved 1e-10 px)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dt (same)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dt / %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw the ghost on the canvas</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ghost:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its integrator:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Its step:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Separation:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t, s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>px</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measure the &amp;Trade-off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run the current scene with every integrator at several steps and plot error against cost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check &amp;Convergence</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rerun the current scene at dt, dt/2, dt/4, dt/8 and fit the order</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Runs the lesson&apos;s scene for %1 s with each integrator.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Error against cost, both on log scales: lower left is better</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(E now − E at the start − energy added or removed on purpose) / |E at the start|: the integrator&apos;s own error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Energy added (+) or removed (−) on purpose by drag, wind, walls, collisions, the pointer and edits, relative to |E at the start|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>|p now − p at the start − impulse of the outside forces|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Energy drift ΔE/|E₀|:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Booked on purpose /|E₀|:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Momentum drift |Δp|:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force evaluations per simulated s:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step cost:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Energy added or taken away on purpose (drag, wind, walls, collisions, your pointer, edits) is booked apart. What is left should be zero: it is the integrator&apos;s own error.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start Counting Again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 ms, %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>force evaluation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>force evaluations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Measuring %1 runs of %2 s…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Running %1 at dt, dt/2, dt/4, dt/8 for %2 s…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not measure: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled after %1 runs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Done: %1 runs against ias15 at dt/8. Each dot is one run; a steeper line is a higher order. Fitted orders: %2.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot run this scene: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>dt = %1 s: error %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: fitted order %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (theory: %1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>cost: force evaluations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error, px</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::ArrowLegendView</name>
    <message>
        <source>An arrow this long stands for %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::BallTable</name>
    <message>
        <source>Balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Double-click a number to type a new one. Undo (Ctrl+Z) takes it back.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>⚠ %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::BallTableModel</name>
    <message>
        <source>world</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Radius. A new radius keeps the density: twice as big is 8 times the mass.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mass, in the mass units of the lesson (a 10 px ball of density 1 has 4189). Independent of the size: a small ball can be heavy.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mass per volume of a sphere: 1 is the density of every ball a lesson does not give a mass.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What a magnetic field acts on (1: like the 10 px reference ball).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How much of its speed this ball keeps in a bounce: 0 stops it dead, 1 keeps it all. &quot;world&quot;: the scene&apos;s value. When two balls hit, the smaller value counts. Clear the cell to go back to the world&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A pinned ball never moves: other balls bounce off it as off a ball too heavy to push.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>x (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vx (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>vy (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>r (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mass (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mass</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>density</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>charge</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>colour</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>restitution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pinned</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pin ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Free ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Give ball %1 the world&apos;s restitution</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>colour: &quot;%1&quot; is not a colour; type a name like red or #e05050</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Colour of ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set %1 of ball %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>restitution: %1 is outside %2; leave it empty for the world&apos;s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::Canvas</name>
    <message>
        <source>Simulation stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 at %2°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1°</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reference (the course&apos;s code) · energy %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>your code stopped: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>your code departs at step %1: %2 balls, the reference has %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>your code departs at step %1 (ball %2, %3 off by %4) · energy %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>your code · agrees for %1 steps · energy %2</source>
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
        <source>your run: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>departs here, step %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paused at t = 0 · press Space to run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tools: press %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>⚠ %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set the velocity of ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Move ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing to paste: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paste a ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Edit its numbers…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop it (v = 0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pin</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pin ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Free ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Copy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Follow it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a ball here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Paste the copied ball here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom in here</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit the box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit all balls</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::CodeDock</name>
    <message>
        <source>Code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The simulation code of this stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C++</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The engine&apos;s own code (sim/)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>JavaScript</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The code students write in the programming course (lessons/code/)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;This stage runs no marked code.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, runs when %1 = %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;The code of this stage in JavaScript, as students write it. It runs beside the engine and moves the balls the same, to the last bit (test_script_reference).&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p class=&apos;missing&apos;&gt;Not written in JavaScript yet: %1.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::EnergyBars</name>
    <message>
        <source>kinetic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>potential</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>total</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Energy bars: kinetic, potential, lost and total energy now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Energy now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lost: energy taken out by drag, bumpy collisions and walls since the bars were shown or the lesson restarted. Energy put in (wind, your hand, an edit) counts as negative lost energy, so the total stays the same unless the computer&apos;s steps are inaccurate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>energy (%1%2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not counted</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::ForceEditorDock</name>
    <message>
        <source>Force editor</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write your own force law. Use x, y (px), vx, vy (px/s), m, r, q, the time t, the box W and H, pi, functions such as sqrt, sin, exp, and your constants.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Custom force on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the formulas give the force F (divided by m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the formulas give the acceleration a</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What the formulas give</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F_x =</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The x part of the force (or acceleration)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>F_y =</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The y part; y points down</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>U =</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Optional: the potential energy of a conservative law, with F = −∇U</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Constants&lt;/b&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>name, e.g. k</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>New constant&apos;s name</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add constant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Constant %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add constant %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Custom force: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::InspectorDock</name>
    <message>
        <source>Inspector</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Click a ball to see its numbers.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity v</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acceleration a</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Mass, radius</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Draw its trail</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>#%1 of %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>m = %1 %2, r = %3 %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>m = %1, r = %2 px</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forces F = m a</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no force acts</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>total</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>in %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::LessonTextView</name>
    <message>
        <source>Open a web page?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The lesson links to
%1

Open it in your web browser?</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::LessonsDock</name>
    <message>
        <source>Lessons</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Teacher notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the goal, expected answers and misconceptions under the lesson text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part A · Motion and walls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part B · Forces</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Part C · Collisions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Beyond the course</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stage %1 of 29</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Beyond the course · %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Try this</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>For the teacher</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;p&gt;This lesson has no teacher notes.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::MainWindow</name>
    <message>
        <source>Parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The computer could not keep up: simulated time was skipped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated seconds per real second ([ slower, ] faster)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Frames drawn per second, and the time to draw one</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wall-clock time of the last simulation step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Number of balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ball pairs tested for contact in the last step, and the contacts found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a saved window geometry; using the default size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a saved layout of the docks; using the default layout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a folder; using the home folder</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not true or false; using the plain theme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>not a text size from %1 to %2; using the usual size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2: %3; opened the first lesson instead</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no built-in lessons were found</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ForceLab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 — ForceLab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Already the slowest speed, %1×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Already the fastest speed, %1×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed %1×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cannot open lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The lesson could not be opened; the running lesson goes on.</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>… and %n more. Show Details… lists every problem.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Text at %1% of its usual size (Ctrl+= larger, Ctrl+− smaller, Ctrl+0 usual)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>speed %1×</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 fps · draw %2 ms</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>step %1 µs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%L1 balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>pairs tested %L1 · contacts %L2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause the simulation (Space)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run the simulation (Space)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>⚠ %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>behind: %1 ms skipped</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>About ForceLab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;ForceLab&lt;/b&gt; %1&lt;br&gt;A workbench for forces and collisions of balls in two dimensions.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step &amp;Back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause and go back by one time step dt, to the world as it was (← or ,)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause and advance by one time step dt (→ or .)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Describe the Scene</source>
        <translation>&amp;Describir la escena</translation>
    </message>
    <message>
        <source>Say in words what is on the stage: the balls, the selected one&apos;s motion, when it reaches a wall, the energy (D)</source>
        <translation>Dice con palabras qué hay en el escenario: las bolas, el movimiento de la seleccionada, cuándo llega a una pared, la energía (D)</translation>
    </message>
    <message>
        <source>&amp;Reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset</source>
        <comment>the word under the button&apos;s icon: short, it has 72 px on the stage</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start the lesson again with its own values (R)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;lower</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slower</source>
        <comment>the word under the button&apos;s icon: short, it has 72 px on the stage</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Half the speed: slow motion down to 1/16× ([)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Faster</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Faster</source>
        <comment>the word under the button&apos;s icon: short, it has 72 px on the stage</comment>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Double the speed, up to %1× (])</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Add Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Add a ball in the middle of the box (B). Right-click the stage to add one where you click.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Delete Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>D&amp;uplicate Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Copy Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Paste Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom in on the middle (+); the mouse wheel zooms in on the pointer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom out (−), to see balls that left the box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit the &amp;Box</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the whole box, as large as it fits (0)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fit &amp;All Balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Zoom so that every ball is seen, in the box or out of it (A)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Follow the Selected Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep the selected ball in the middle of the view as it moves (F)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Open Lesson…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open a lesson file from disk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save Scene as Lesson…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the balls as they are now and the live settings as a lesson file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Screens&amp;hot…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Picture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save a picture of the canvas as PNG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Re&amp;cord Trajectory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Record</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Record the path of the selected ball (or of all balls when none is selected)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording ball #%1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Recording every ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Export Trajectory…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the recorded trajectory as CSV (time, ball, position, velocity)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Teacher &amp;Handbook…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write every lesson with its teacher notes as one printable HTML page</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Previous Lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Next Lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Stage View (Projector)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The simulation fills the screen with large controls beside it, for a projector (F11; Escape leaves)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stage</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Larger Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Larger text in every panel and on the stage (Ctrl+=)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>S&amp;maller Text</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Smaller text in every panel and on the stage (Ctrl+−)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Usual Text Size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P&amp;rojector Theme</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>White box, dark thick outlines, colour-blind-safe balls and larger text everywhere (always on in the stage view)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Picture at &amp;Double Size…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save the stage at twice the screen&apos;s resolution, for print</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About ForceLab</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Pixels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show px, px/s and mass units, as the program computes them</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;SI (m, kg, N, J)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show metres, kilograms, newtons and joules at the scale set below</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How many pixels make a metre, and how many kilograms a mass unit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SI Scale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> px</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> kg</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 m is</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1 mass unit is</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SI &amp;Scale: %1 px = 1 m, 1 mass unit = %2 kg…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Accuracy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Units</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show: what the stage draws</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>File</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open Lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lesson files (*.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lesson not saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Saved %n ball(s) and the settings to %1 as “%2”. %3</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Picture not saved: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved the picture to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Picture at Double Size</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save Picture</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Teacher Handbook</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>HTML (*.html)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1
The handbook was not written; an old file there is unchanged.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Handbook written to %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Nothing recorded yet: switch on Record Trajectory (Ctrl+Shift+R) first</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export Trajectory</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrote %L1 rows to %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::NumberControl</name>
    <message>
        <source>%1, slider</source>
        <translation>%1, deslizador</translation>
    </message>
    <message>
        <source>%1, value</source>
        <translation>%1, valor</translation>
    </message>
</context>
<context>
    <name>forcelab::OverlayActions</name>
    <message>
        <source>&amp;Show</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Velocity arrows</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Acceleration arrows (a = F/m)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Force arrows (net force F = m a)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forces &amp;by source (one arrow per force)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Paths</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Centre of mass and its path</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>M&amp;omenta diagram (p = m v, tip to tail)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tops of the flights, with their &amp;heights</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Readout of the selected ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Totals: energy and momentum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Mark touching balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Markers (centres, anchors, homes)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arrow &amp;length</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Auto: readable (about 45 px)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The lesson&apos;s scale (×1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>×%1 the lesson&apos;s scale</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arrow scale ×&amp;2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arrow scale ÷2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arrow scale &amp;from now</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::ParameterPanel</name>
    <message>
        <source>Show all parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Besides the lesson&apos;s own controls, show every setting of the world</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Box and walls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Drag</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wind</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Random acceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Point force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spring</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Gravity between balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Homing</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pointer force</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Collisions</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>%n more setting(s) under &quot;Show all parameters&quot;.</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Tick to switch %1 on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 to %2%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>bottom</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Walls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A wall that is not ticked is open</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time.seed: &quot;%1&quot; is not a whole number from 0 to 18446744073709551615</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Seed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Random numbers (wind, random acceleration) start from this seed when the balls are placed again</source>
        <translation type="unfinished"></translation>
    </message>
    <message numerus="yes">
        <source>Place %n random ball(s)</source>
        <translation type="unfinished">
            <numerusform></numerusform>
            <numerusform></numerusform>
        </translation>
    </message>
    <message>
        <source>Place random balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Random balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>How many balls are placed at random (besides the lesson&apos;s own); changing it starts again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slowest random ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fastest random ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Random balls start with a speed of at least this; changing it starts again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Random balls start with a speed of at most this; changing it starts again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Place balls fully inside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Let balls start partly outside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start fully inside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off: a ball&apos;s centre may be anywhere in the box, so it can start partly outside a wall (stage 4&apos;s bug). Changing it places the balls again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated seconds per real second: below 1 is slow motion (%1× to %2×)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::PlotsDock</name>
    <message>
        <source>Plots</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>kinetic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>potential</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>total</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>|p|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>p_x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>p_y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>one step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plots of energy, momentum and step cost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Energy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Energy bars</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Graph</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Momentum</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cost of a step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step cost</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Momentum (×10¹² mass·px²/s²)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speeds</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Computer time per step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>µs</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::PredictDock</name>
    <message>
        <source>Predict</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Your prediction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>your guess</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lock in and run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the answer now</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Next question</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This lesson asks no question before it runs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Make your prediction while the lesson waits at t = 0, then run it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Type a number first (for example 200).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pick an answer first.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Still stopping the last measurement; try again in a moment.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locked in. Working out the answer…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled. Change your answer or lock it in again.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Locked in. Watch: the answer comes at t = %1 s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>It could not be measured in this run (the lesson&apos;s sentence “%1”). Did a setting change it?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>You chose &lt;b&gt;%1&lt;/b&gt;. Measured: &lt;b&gt;%2 %3&lt;/b&gt;, so the answer is &lt;b&gt;%4&lt;/b&gt;. %5</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Well predicted!</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Why was it different?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> (%1%)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>You said &lt;b&gt;%1 %2&lt;/b&gt;. Measured: &lt;b&gt;%3 %2&lt;/b&gt;. You were %4 %2 off%5.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;small&gt;The run measured what the lesson says: “%1”.&lt;/small&gt;</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::QuantityGraph</name>
    <message>
        <source>x position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>y position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>velocity v_x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>velocity v_y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>kinetic energy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>potential energy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>total energy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>momentum p_x</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>momentum p_y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Quantity to graph</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ball to graph</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>of</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: E₀, nothing takes energy away</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: x₀ + v₀t + ½gt²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: x₀ + v₀t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: y₀ + v₀t + ½gt²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: y₀ + v₀t</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: v₀ + gt</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: v₀, constant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: |v₀ + gt|</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: |v₀|, constant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: ½m|v₀ + gt|²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: ½m|v₀|², constant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: mgh, h of the flight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: 0, no gravity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: E₀, constant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: m(v₀ + gt)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>theory: mv₀, constant</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 of %2 (%3%4)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::SaveLessonDialog</name>
    <message>
        <source>Save Scene as Lesson</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The scene is saved as a new lesson with your title and text. Of the claims and questions of “%1”, only those that still hold in this scene are kept; the others are listed after saving.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plain text; an empty line starts a new paragraph.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Keep the teacher notes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The goal, the minutes and the misconceptions. The answers to the challenges are never kept: the new lesson has no challenges.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>C&amp;hoose…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Title:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Te&amp;xt:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lesson files (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The lesson needs a title.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>“%1” has a number or a comparison (“%2”) that nothing measures on this scene, and a lesson must not say what it does not check. Write it without, or add a claim to the file later.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose the file to save to.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::SettingsEditor</name>
    <message>
        <source>Random balls from %1 to %2 px/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mass: %1 is outside %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not placed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Moved to (%1, %2) px, touching, so it does not overlap</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Not added: the world holds at most %1 balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Delete ball %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duplicate ball %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::SimulationController</name>
    <message>
        <source>%1 pane: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>your code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>spawn.count: %1 listed + %2 random balls is more than the limit of %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time scale: %1 is outside %2 to %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ghost: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::SpeedHistogram</name>
    <message>
        <source>Histogram of the balls&apos; speeds with the Maxwell–Boltzmann curve</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Maxwell–Boltzmann (2D), same energy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>speed (px/s)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>speed (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1balls per %2 %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Speeds of %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ball</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::StageSliders</name>
    <message>
        <source>Left</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Right</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Top</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A wall whose button is not pressed is open: a ball leaves through it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off: a ball&apos;s centre may be anywhere in the box, so it can start partly outside a wall. Changing it places the balls again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Place balls fully inside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Let balls start partly outside</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slowest random ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fastest random ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Walls: &lt;b&gt;%1&lt;/b&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Slowest random ball: &lt;b&gt;%1&lt;/b&gt; %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fastest random ball: &lt;b&gt;%1&lt;/b&gt; %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch off</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Switch on</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start fully inside: &lt;b&gt;%1&lt;/b&gt;</source>
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
</context>
<context>
    <name>forcelab::StageToolTitle</name>
    <message>
        <source>Close (the tool&apos;s key again)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::StageView</name>
    <message>
        <source>Sliders</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show the lesson&apos;s sliders under the box in the stage view (S)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Balls</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show every ball&apos;s numbers under the box, to type new ones (T)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Stopped:&lt;/b&gt; %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = %1 s   %2× speed</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::StepApartDock</name>
    <message>
        <source>One Step Apart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>all</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sub-step shown</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sub-step shown:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>◀ Step back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step ▶</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Pause to take a step apart: it is worked out for one step at a time, not for every frame.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>There is no ball to follow.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Sub-step %1 of %2: h = %3 s, starting at</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The step starts: h = %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Force: %1 adds its acceleration</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>its own part: (%1, %2) px/s²</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acceleration: all the forces added up</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Acceleration k%1, at a trial state (Runge-Kutta)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no force is switched on: the acceleration stays 0</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity changes</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Position moves</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>with the %1 accelerations above, weighted 1, 2, 2, 1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no wall touched: nothing changed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nothing changed for this ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Detection: which balls touch?</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>ball %1 and ball %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>no ball touches ball %1 (%2 touching pairs in all)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>touching: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Response with ball %1: the velocities change</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>they are moving apart already: no change</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Δvx = %1 px/s, Δvy = %2 px/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Push-apart from ball %1: out of each other</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>overlap %1 px; Δx = %2 px, Δy = %3 px</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check: the script&apos;s step against the engine&apos;s (C++)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>matches the engine bit for bit</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>differs from the engine by Δx = %1, Δy = %2 px, Δvx = %3, Δvy = %4 px/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>One step, taken apart</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ball %1, step %2 → %3, in the order the JavaScript runs it. Changed values are highlighted.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::StopwatchDock</name>
    <message>
        <source>Stopwatch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>by hand</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>on the event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start the stopwatch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>after events:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop the stopwatch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Events before the stopwatch stops</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a bounce (moving down, then up)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the top of a flight</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>crossing the line x =</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>crossing the line y =</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>a full turn round the centre</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Event</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line position</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Line at</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ball watched</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Ball</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Arm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Waiting…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start again</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Last times: %1</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::StudentCodeDock</name>
    <message>
        <source>Your Code</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Rewrite:</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>JavaScript file to rewrite</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The stage&apos;s code, one file per rule. Pick one and write your own version.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Your JavaScript</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run beside the reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Runs your version in place of the course&apos;s, beside the reference (Ctrl+Return)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Takes your code off the canvas</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back to the course&apos;s file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Throws away your changes to this file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 (yours)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Change the code above, then press Run: your version runs beside the course&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Your changes: %1. Press Run to see them beside the reference.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Your code stopped. %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Departs at step %1: your code has %2 balls, the reference %3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Departs at step %1 (t = %2 s), ball %3: %4 is %5 in your code and %6 in the reference, %7 apart. Now the balls are up to %8 apart.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Agrees with the reference for all %1 steps so far (x, y, vx and vy to 9 significant digits).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::TimelineBar</name>
    <message>
        <source>Step back: pause and show the world one step dt earlier</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step: re-run the next recorded step, or take a new one at the latest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The recorded past: drag to see the world at any step of it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step back</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Step forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timeline: the recorded steps</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time shown, of the time recorded</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = %1 s of %2 s</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>forcelab::TraceCheck</name>
    <message>
        <source>Check a Student&apos;s &amp;Trace…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check a trace a student&apos;s own program wrote (CSV or JSON: step, ball, x, y, vx, vy) against this run: where it first departs, and why</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Check a Student&apos;s Trace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Traces (*.csv *.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: a trace is still being checked; wait for its result</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 cannot be checked: %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 agrees with the run at every one of its %2 rows (to step %3, t = %4 s): the largest difference is %5.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 departs from the run at step %2 (t = %3 s), ball %4: %5 is %6 where the run has %7, off by %8.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Likely cause: %1. The numbers follow the run with %2: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No known mistake explains it: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The canvas does not go there: step %1 is past the %2 steps it runs to at once.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Student&apos;s trace</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>student&apos;s ball %1, step %2</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
