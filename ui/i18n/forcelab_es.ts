<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es">
<context>
    <name>BallClipboard</name>
    <message>
        <source>the clipboard holds %1 characters, more than a ball&apos;s %2</source>
        <translation>el portapapeles tiene %1 caracteres, más que los %2 de una bola</translation>
    </message>
    <message>
        <source>the clipboard does not hold a ball</source>
        <translation>el portapapeles no contiene una bola</translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has an unknown field &quot;%1&quot;</source>
        <translation>la bola del portapapeles tiene un campo desconocido «%1»</translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has no number &quot;%1&quot;</source>
        <translation>la bola del portapapeles no tiene el número «%1»</translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has &quot;pinned&quot; that is not true or false</source>
        <translation>la bola del portapapeles tiene un «pinned» que no es true ni false</translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has a restitution that is not a number from 0 to 1</source>
        <translation>la bola del portapapeles tiene una restitución que no es un número de 0 a 1</translation>
    </message>
    <message>
        <source>the clipboard&apos;s ball has no valid colour</source>
        <translation>la bola del portapapeles no tiene un color válido</translation>
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
        <translation>Cambiar la velocidad a %1×</translation>
    </message>
    <message>
        <source>Walls: is the ball outside the box?</source>
        <translation>Paredes: ¿está la bola fuera de la caja?</translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation>Límite de rapidez</translation>
    </message>
    <message>
        <source>Rule %1</source>
        <translation>Regla %1</translation>
    </message>
    <message>
        <source>Goal:</source>
        <translation>Objetivo:</translation>
    </message>
    <message>
        <source>about %1 minutes</source>
        <translation>unos %1 minutos</translation>
    </message>
    <message>
        <source>Expected answers</source>
        <translation>Respuestas esperadas</translation>
    </message>
    <message>
        <source>Common misconceptions</source>
        <translation>Ideas erróneas frecuentes</translation>
    </message>
    <message>
        <source>What the scene is checked to show</source>
        <translation>Lo que se comprueba que muestra la escena</translation>
    </message>
    <message>
        <source>ForceLab: teacher&apos;s handbook</source>
        <translation>ForceLab: manual del profesor</translation>
    </message>
    <message>
        <source>One section per lesson: the goal, the time it takes, the text students read, the challenges with their expected answers, the misconceptions to expect, and what the scene is checked to show (forcelab-cli check).</source>
        <translation>Una sección por lección: el objetivo, el tiempo que lleva, el texto que leen los alumnos, los retos con sus respuestas esperadas, las ideas erróneas que cabe esperar y lo que se comprueba que muestra la escena (forcelab-cli check).</translation>
    </message>
    <message>
        <source>Showcase</source>
        <translation>Muestra</translation>
    </message>
    <message>
        <source>Stage %1 of 29</source>
        <translation>Etapa %1 de 29</translation>
    </message>
    <message>
        <source>Beyond the course</source>
        <translation>Más allá del curso</translation>
    </message>
    <message>
        <source>Challenges</source>
        <translation>Retos</translation>
    </message>
    <message>
        <source>For the teacher</source>
        <translation>Para el profesor</translation>
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
        <translation>Precisión</translation>
    </message>
    <message>
        <source>Drift</source>
        <translation>Deriva</translation>
    </message>
    <message>
        <source>Ghost</source>
        <translation>Fantasma</translation>
    </message>
    <message>
        <source>Trade-off</source>
        <translation>Compromiso</translation>
    </message>
    <message>
        <source>Off</source>
        <translation>Desactivado</translation>
    </message>
    <message>
        <source>Compare with another integrator</source>
        <translation>Comparar con otro integrador</translation>
    </message>
    <message>
        <source>Sensitivity twin (moved 1e-10 px)</source>
        <translation>Gemelo de sensibilidad (movido 1e-10 px)</translation>
    </message>
    <message>
        <source>dt (same)</source>
        <translation>dt (igual)</translation>
    </message>
    <message>
        <source>dt / %1</source>
        <translation>dt / %1</translation>
    </message>
    <message>
        <source>Draw the ghost on the canvas</source>
        <translation>Dibujar el fantasma en el lienzo</translation>
    </message>
    <message>
        <source>Ghost:</source>
        <translation>Fantasma:</translation>
    </message>
    <message>
        <source>Its integrator:</source>
        <translation>Su integrador:</translation>
    </message>
    <message>
        <source>Its step:</source>
        <translation>Su paso:</translation>
    </message>
    <message>
        <source>Separation:</source>
        <translation>Separación:</translation>
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
        <translation>Medir el &amp;compromiso</translation>
    </message>
    <message>
        <source>Run the current scene with every integrator at several steps and plot error against cost</source>
        <translation>Ejecuta la escena actual con cada integrador a varios pasos y representa el error frente al coste</translation>
    </message>
    <message>
        <source>Check &amp;Convergence</source>
        <translation>Comprobar la &amp;convergencia</translation>
    </message>
    <message>
        <source>Rerun the current scene at dt, dt/2, dt/4, dt/8 and fit the order</source>
        <translation>Vuelve a ejecutar la escena actual con dt, dt/2, dt/4, dt/8 y ajusta el orden</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Runs the lesson&apos;s scene for %1 s with each integrator.</source>
        <translation>Ejecuta la escena de la lección durante %1 s con cada integrador.</translation>
    </message>
    <message>
        <source>Error against cost, both on log scales: lower left is better</source>
        <translation>Error frente a coste, ambos en escala logarítmica: abajo a la izquierda es mejor</translation>
    </message>
    <message>
        <source>(E now − E at the start − energy added or removed on purpose) / |E at the start|: the integrator&apos;s own error</source>
        <translation>(E ahora − E al principio − energía añadida o quitada a propósito) / |E al principio|: el error propio del integrador</translation>
    </message>
    <message>
        <source>Energy added (+) or removed (−) on purpose by drag, wind, walls, collisions, the pointer and edits, relative to |E at the start|</source>
        <translation>Energía añadida (+) o quitada (−) a propósito por el rozamiento, el viento, las paredes, los choques, el puntero y las ediciones, respecto a |E al principio|</translation>
    </message>
    <message>
        <source>|p now − p at the start − impulse of the outside forces|</source>
        <translation>|p ahora − p al principio − impulso de las fuerzas exteriores|</translation>
    </message>
    <message>
        <source>Energy drift ΔE/|E₀|:</source>
        <translation>Deriva de la energía ΔE/|E₀|:</translation>
    </message>
    <message>
        <source>Booked on purpose /|E₀|:</source>
        <translation>Contabilizada a propósito /|E₀|:</translation>
    </message>
    <message>
        <source>Momentum drift |Δp|:</source>
        <translation>Deriva del momento |Δp|:</translation>
    </message>
    <message>
        <source>Force evaluations per simulated s:</source>
        <translation>Evaluaciones de la fuerza por s simulado:</translation>
    </message>
    <message>
        <source>Step cost:</source>
        <translation>Coste por paso:</translation>
    </message>
    <message>
        <source>Energy added or taken away on purpose (drag, wind, walls, collisions, your pointer, edits) is booked apart. What is left should be zero: it is the integrator&apos;s own error.</source>
        <translation>La energía añadida o quitada a propósito (rozamiento, viento, paredes, choques, tu puntero, ediciones) se contabiliza aparte. Lo que queda debería ser cero: es el error propio del integrador.</translation>
    </message>
    <message>
        <source>Start Counting Again</source>
        <translation>Empezar a contar de nuevo</translation>
    </message>
    <message>
        <source>%1 ms, %2</source>
        <translation>%1 ms, %2</translation>
    </message>
    <message>
        <source>force evaluation</source>
        <translation>evaluación de la fuerza</translation>
    </message>
    <message>
        <source>force evaluations</source>
        <translation>evaluaciones de la fuerza</translation>
    </message>
    <message>
        <source>Measuring %1 runs of %2 s…</source>
        <translation>Midiendo %1 ejecuciones de %2 s…</translation>
    </message>
    <message>
        <source>Running %1 at dt, dt/2, dt/4, dt/8 for %2 s…</source>
        <translation>Ejecutando %1 con dt, dt/2, dt/4, dt/8 durante %2 s…</translation>
    </message>
    <message>
        <source>Could not measure: %1</source>
        <translation>No se pudo medir: %1</translation>
    </message>
    <message>
        <source>Cancelled after %1 runs.</source>
        <translation>Cancelado tras %1 ejecuciones.</translation>
    </message>
    <message>
        <source>Done: %1 runs against ias15 at dt/8. Each dot is one run; a steeper line is a higher order. Fitted orders: %2.</source>
        <translation>Hecho: %1 ejecuciones frente a ias15 con dt/8. Cada punto es una ejecución; una recta más inclinada es un orden mayor. Órdenes ajustados: %2.</translation>
    </message>
    <message>
        <source>%1 cannot run this scene: %2</source>
        <translation>%1 no puede ejecutar esta escena: %2</translation>
    </message>
    <message>
        <source>dt = %1 s: error %2</source>
        <translation>dt = %1 s: error %2</translation>
    </message>
    <message>
        <source>%1: fitted order %2</source>
        <translation>%1: orden ajustado %2</translation>
    </message>
    <message>
        <source> (theory: %1)</source>
        <translation> (teoría: %1)</translation>
    </message>
    <message>
        <source>cost: force evaluations</source>
        <translation>coste: evaluaciones de la fuerza</translation>
    </message>
    <message>
        <source>error, px</source>
        <translation>error, px</translation>
    </message>
</context>
<context>
    <name>forcelab::ArrowLegendView</name>
    <message>
        <source>An arrow this long stands for %1</source>
        <translation>Una flecha así de larga representa %1</translation>
    </message>
</context>
<context>
    <name>forcelab::BallTable</name>
    <message>
        <source>Balls</source>
        <translation>Bolas</translation>
    </message>
    <message>
        <source>Double-click a number to type a new one. Undo (Ctrl+Z) takes it back.</source>
        <translation>Haz doble clic en un número para escribir otro. Deshacer (Ctrl+Z) lo revierte.</translation>
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
        <translation>mundo</translation>
    </message>
    <message>
        <source>Radius. A new radius keeps the density: twice as big is 8 times the mass.</source>
        <translation>Radio. Un radio nuevo conserva la densidad: el doble de grande son 8 veces la masa.</translation>
    </message>
    <message>
        <source>Mass, in the mass units of the lesson (a 10 px ball of density 1 has 4189). Independent of the size: a small ball can be heavy.</source>
        <translation>Masa, en las unidades de masa de la lección (una bola de 10 px con densidad 1 tiene 4189). No depende del tamaño: una bola pequeña puede ser pesada.</translation>
    </message>
    <message>
        <source>Mass per volume of a sphere: 1 is the density of every ball a lesson does not give a mass.</source>
        <translation>Masa por volumen de una esfera: 1 es la densidad de toda bola a la que la lección no da masa.</translation>
    </message>
    <message>
        <source>What a magnetic field acts on (1: like the 10 px reference ball).</source>
        <translation>Sobre lo que actúa un campo magnético (1: como la bola de referencia de 10 px).</translation>
    </message>
    <message>
        <source>How much of its speed this ball keeps in a bounce: 0 stops it dead, 1 keeps it all. &quot;world&quot;: the scene&apos;s value. When two balls hit, the smaller value counts. Clear the cell to go back to the world&apos;s.</source>
        <translation>Cuánta rapidez conserva esta bola en un rebote: 0 la detiene en seco, 1 la conserva toda. «mundo»: el valor de la escena. Cuando chocan dos bolas, cuenta el valor menor. Vacía la celda para volver al del mundo.</translation>
    </message>
    <message>
        <source>A pinned ball never moves: other balls bounce off it as off a ball too heavy to push.</source>
        <translation>Una bola fijada nunca se mueve: las demás rebotan en ella como en una bola demasiado pesada para empujarla.</translation>
    </message>
    <message>
        <source>Ball</source>
        <translation>Bola</translation>
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
        <translation>masa (%1)</translation>
    </message>
    <message>
        <source>mass</source>
        <translation>masa</translation>
    </message>
    <message>
        <source>density</source>
        <translation>densidad</translation>
    </message>
    <message>
        <source>charge</source>
        <translation>carga</translation>
    </message>
    <message>
        <source>colour</source>
        <translation>color</translation>
    </message>
    <message>
        <source>restitution</source>
        <translation>restitución</translation>
    </message>
    <message>
        <source>pinned</source>
        <translation>fijada</translation>
    </message>
    <message>
        <source>Pin ball %1</source>
        <translation>Fijar la bola %1</translation>
    </message>
    <message>
        <source>Free ball %1</source>
        <translation>Soltar la bola %1</translation>
    </message>
    <message>
        <source>Give ball %1 the world&apos;s restitution</source>
        <translation>Dar a la bola %1 la restitución del mundo</translation>
    </message>
    <message>
        <source>colour: &quot;%1&quot; is not a colour; type a name like red or #e05050</source>
        <translation>color: «%1» no es un color; escribe un nombre como red o #e05050</translation>
    </message>
    <message>
        <source>Colour of ball %1</source>
        <translation>Color de la bola %1</translation>
    </message>
    <message>
        <source>%1: &quot;%2&quot; is not a number</source>
        <translation>%1: «%2» no es un número</translation>
    </message>
    <message>
        <source>Set %1 of ball %2</source>
        <translation>Cambiar %1 de la bola %2</translation>
    </message>
    <message>
        <source>restitution: %1 is outside %2; leave it empty for the world&apos;s</source>
        <translation>restitución: %1 está fuera de %2; déjala vacía para usar la del mundo</translation>
    </message>
</context>
<context>
    <name>forcelab::Canvas</name>
    <message>
        <source>Simulation stage</source>
        <translation>Escenario de la simulación</translation>
    </message>
    <message>
        <source>%1 at %2°</source>
        <translation>%1 a %2°</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>reference (the course&apos;s code) · energy %1</source>
        <translation>referencia (el código del curso) · energía %1</translation>
    </message>
    <message>
        <source>your code stopped: %1</source>
        <translation>tu código se ha detenido: %1</translation>
    </message>
    <message>
        <source>your code departs at step %1: %2 balls, the reference has %3</source>
        <translation>tu código se separa en el paso %1: %2 bolas, la referencia tiene %3</translation>
    </message>
    <message>
        <source>your code departs at step %1 (ball %2, %3 off by %4) · energy %5</source>
        <translation>tu código se separa en el paso %1 (bola %2, %3 difiere en %4) · energía %5</translation>
    </message>
    <message>
        <source>your code · agrees for %1 steps · energy %2</source>
        <translation>tu código · coincide durante %1 pasos · energía %2</translation>
    </message>
    <message>
        <source>on</source>
        <translation>sí</translation>
    </message>
    <message>
        <source>off</source>
        <translation>no</translation>
    </message>
    <message>
        <source>your run: %1</source>
        <translation>tu ejecución: %1</translation>
    </message>
    <message>
        <source>departs here, step %1</source>
        <translation>se separa aquí, paso %1</translation>
    </message>
    <message>
        <source>Paused at t = 0 · press Space to run</source>
        <translation>En pausa en t = 0 · pulsa Espacio para ejecutar</translation>
    </message>
    <message>
        <source>Tools: press %1</source>
        <translation>Herramientas: pulsa %1</translation>
    </message>
    <message>
        <source>⚠ %1</source>
        <translation>⚠ %1</translation>
    </message>
    <message>
        <source>Set the velocity of ball %1</source>
        <translation>Fijar la velocidad de la bola %1</translation>
    </message>
    <message>
        <source>Move ball %1</source>
        <translation>Mover la bola %1</translation>
    </message>
    <message>
        <source>Add a ball</source>
        <translation>Añadir una bola</translation>
    </message>
    <message>
        <source>Nothing to paste: %1</source>
        <translation>Nada que pegar: %1</translation>
    </message>
    <message>
        <source>Paste a ball</source>
        <translation>Pegar una bola</translation>
    </message>
    <message>
        <source>Ball %1</source>
        <translation>Bola %1</translation>
    </message>
    <message>
        <source>Edit its numbers…</source>
        <translation>Editar sus números…</translation>
    </message>
    <message>
        <source>Stop it (v = 0)</source>
        <translation>Pararla (v = 0)</translation>
    </message>
    <message>
        <source>Stop ball %1</source>
        <translation>Parar la bola %1</translation>
    </message>
    <message>
        <source>Pin</source>
        <translation>Fijar</translation>
    </message>
    <message>
        <source>Pin ball %1</source>
        <translation>Fijar la bola %1</translation>
    </message>
    <message>
        <source>Free ball %1</source>
        <translation>Soltar la bola %1</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>Duplicar</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>Copiar</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Borrar</translation>
    </message>
    <message>
        <source>Follow it</source>
        <translation>Seguirla</translation>
    </message>
    <message>
        <source>Add a ball here</source>
        <translation>Añadir una bola aquí</translation>
    </message>
    <message>
        <source>Paste the copied ball here</source>
        <translation>Pegar aquí la bola copiada</translation>
    </message>
    <message>
        <source>Zoom in here</source>
        <translation>Acercar aquí</translation>
    </message>
    <message>
        <source>Zoom out</source>
        <translation>Alejar</translation>
    </message>
    <message>
        <source>Fit the box</source>
        <translation>Ajustar a la caja</translation>
    </message>
    <message>
        <source>Fit all balls</source>
        <translation>Ajustar a todas las bolas</translation>
    </message>
</context>
<context>
    <name>forcelab::CodeDock</name>
    <message>
        <source>Code</source>
        <translation>Código</translation>
    </message>
    <message>
        <source>The simulation code of this stage</source>
        <translation>El código de la simulación de esta etapa</translation>
    </message>
    <message>
        <source>C++</source>
        <translation>C++</translation>
    </message>
    <message>
        <source>The engine&apos;s own code (sim/)</source>
        <translation>El código propio del motor (sim/)</translation>
    </message>
    <message>
        <source>JavaScript</source>
        <translation>JavaScript</translation>
    </message>
    <message>
        <source>The code students write in the programming course (lessons/code/)</source>
        <translation>El código que escriben los alumnos en el curso de programación (lessons/code/)</translation>
    </message>
    <message>
        <source>&lt;p&gt;This stage runs no marked code.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Esta etapa no ejecuta código marcado.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>, runs when %1 = %2</source>
        <translation>, se ejecuta cuando %1 = %2</translation>
    </message>
    <message>
        <source>&lt;p&gt;The code of this stage in JavaScript, as students write it. It runs beside the engine and moves the balls the same, to the last bit (test_script_reference).&lt;/p&gt;</source>
        <translation>&lt;p&gt;El código de esta etapa en JavaScript, tal como lo escriben los alumnos. Se ejecuta junto al motor y mueve las bolas igual, hasta el último bit (test_script_reference).&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;p class=&apos;missing&apos;&gt;Not written in JavaScript yet: %1.&lt;/p&gt;</source>
        <translation>&lt;p class=&apos;missing&apos;&gt;Aún no escrito en JavaScript: %1.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>forcelab::EnergyBars</name>
    <message>
        <source>kinetic</source>
        <translation>cinética</translation>
    </message>
    <message>
        <source>potential</source>
        <translation>potencial</translation>
    </message>
    <message>
        <source>lost</source>
        <translation>perdida</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source>Energy bars: kinetic, potential, lost and total energy now</source>
        <translation>Barras de energía: energía cinética, potencial, perdida y total ahora</translation>
    </message>
    <message>
        <source>Energy now</source>
        <translation>Energía ahora</translation>
    </message>
    <message>
        <source>Lost: energy taken out by drag, bumpy collisions and walls since the bars were shown or the lesson restarted. Energy put in (wind, your hand, an edit) counts as negative lost energy, so the total stays the same unless the computer&apos;s steps are inaccurate.</source>
        <translation>Perdida: la energía que se llevaron el rozamiento, los choques no elásticos y las paredes desde que se mostraron las barras o se reinició la lección. La energía aportada (viento, tu mano, una edición) cuenta como energía perdida negativa, así que el total no cambia salvo que los pasos del ordenador sean imprecisos.</translation>
    </message>
    <message>
        <source>energy (%1%2)</source>
        <translation>energía (%1%2)</translation>
    </message>
    <message>
        <source>not counted</source>
        <translation>no contada</translation>
    </message>
</context>
<context>
    <name>forcelab::ForceEditorDock</name>
    <message>
        <source>Force editor</source>
        <translation>Editor de fuerzas</translation>
    </message>
    <message>
        <source>Write your own force law. Use x, y (px), vx, vy (px/s), m, r, q, the time t, the box W and H, pi, functions such as sqrt, sin, exp, and your constants.</source>
        <translation>Escribe tu propia ley de fuerza. Usa x, y (px), vx, vy (px/s), m, r, q, el tiempo t, la caja W y H, pi, funciones como sqrt, sin, exp, y tus constantes.</translation>
    </message>
    <message>
        <source>Custom force on</source>
        <translation>Fuerza propia activada</translation>
    </message>
    <message>
        <source>the formulas give the force F (divided by m)</source>
        <translation>las fórmulas dan la fuerza F (dividida por m)</translation>
    </message>
    <message>
        <source>the formulas give the acceleration a</source>
        <translation>las fórmulas dan la aceleración a</translation>
    </message>
    <message>
        <source>What the formulas give</source>
        <translation>Lo que dan las fórmulas</translation>
    </message>
    <message>
        <source>F_x =</source>
        <translation>F_x =</translation>
    </message>
    <message>
        <source>The x part of the force (or acceleration)</source>
        <translation>La parte x de la fuerza (o de la aceleración)</translation>
    </message>
    <message>
        <source>F_y =</source>
        <translation>F_y =</translation>
    </message>
    <message>
        <source>The y part; y points down</source>
        <translation>La parte y; y apunta hacia abajo</translation>
    </message>
    <message>
        <source>U =</source>
        <translation>U =</translation>
    </message>
    <message>
        <source>Optional: the potential energy of a conservative law, with F = −∇U</source>
        <translation>Opcional: la energía potencial de una ley conservativa, con F = −∇U</translation>
    </message>
    <message>
        <source>&lt;b&gt;Constants&lt;/b&gt;</source>
        <translation>&lt;b&gt;Constantes&lt;/b&gt;</translation>
    </message>
    <message>
        <source>name, e.g. k</source>
        <translation>nombre, p. ej. k</translation>
    </message>
    <message>
        <source>New constant&apos;s name</source>
        <translation>Nombre de la constante nueva</translation>
    </message>
    <message>
        <source>Add constant</source>
        <translation>Añadir constante</translation>
    </message>
    <message>
        <source>Constant %1</source>
        <translation>Constante %1</translation>
    </message>
    <message>
        <source>Add constant %1</source>
        <translation>Añadir la constante %1</translation>
    </message>
    <message>
        <source>Custom force: %1</source>
        <translation>Fuerza propia: %1</translation>
    </message>
</context>
<context>
    <name>forcelab::InspectorDock</name>
    <message>
        <source>Inspector</source>
        <translation>Inspector</translation>
    </message>
    <message>
        <source>Click a ball to see its numbers.</source>
        <translation>Haz clic en una bola para ver sus números.</translation>
    </message>
    <message>
        <source>Ball</source>
        <translation>Bola</translation>
    </message>
    <message>
        <source>Position x</source>
        <translation>Posición x</translation>
    </message>
    <message>
        <source>Velocity v</source>
        <translation>Velocidad v</translation>
    </message>
    <message>
        <source>Acceleration a</source>
        <translation>Aceleración a</translation>
    </message>
    <message>
        <source>Mass, radius</source>
        <translation>Masa, radio</translation>
    </message>
    <message>
        <source>Draw its trail</source>
        <translation>Dibujar su estela</translation>
    </message>
    <message>
        <source>#%1 of %2</source>
        <translation>n.º %1 de %2</translation>
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
        <translation>Fuerzas F = m a</translation>
    </message>
    <message>
        <source>no force acts</source>
        <translation>no actúa ninguna fuerza</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source>in %1</source>
        <translation>en %1</translation>
    </message>
</context>
<context>
    <name>forcelab::LessonTextView</name>
    <message>
        <source>Open a web page?</source>
        <translation>¿Abrir una página web?</translation>
    </message>
    <message>
        <source>The lesson links to
%1

Open it in your web browser?</source>
        <translation>La lección enlaza con
%1

¿Abrirla en tu navegador?</translation>
    </message>
</context>
<context>
    <name>forcelab::LessonsDock</name>
    <message>
        <source>Lessons</source>
        <translation>Lecciones</translation>
    </message>
    <message>
        <source>Teacher notes</source>
        <translation>Notas del profesor</translation>
    </message>
    <message>
        <source>Show the goal, expected answers and misconceptions under the lesson text</source>
        <translation>Muestra el objetivo, las respuestas esperadas y las ideas erróneas bajo el texto de la lección</translation>
    </message>
    <message>
        <source>Part A · Motion and walls</source>
        <translation>Parte A · Movimiento y paredes</translation>
    </message>
    <message>
        <source>Part B · Forces</source>
        <translation>Parte B · Fuerzas</translation>
    </message>
    <message>
        <source>Part C · Collisions</source>
        <translation>Parte C · Choques</translation>
    </message>
    <message>
        <source>Beyond the course</source>
        <translation>Más allá del curso</translation>
    </message>
    <message>
        <source>Stage %1 of 29</source>
        <translation>Etapa %1 de 29</translation>
    </message>
    <message>
        <source>Beyond the course · %1</source>
        <translation>Más allá del curso · %1</translation>
    </message>
    <message>
        <source>Try this</source>
        <translation>Prueba esto</translation>
    </message>
    <message>
        <source>For the teacher</source>
        <translation>Para el profesor</translation>
    </message>
    <message>
        <source>&lt;p&gt;This lesson has no teacher notes.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Esta lección no tiene notas del profesor.&lt;/p&gt;</translation>
    </message>
</context>
<context>
    <name>forcelab::MainWindow</name>
    <message>
        <source>Parameters</source>
        <translation>Parámetros</translation>
    </message>
    <message>
        <source>Balls</source>
        <translation>Bolas</translation>
    </message>
    <message>
        <source>&amp;Undo</source>
        <translation>&amp;Deshacer</translation>
    </message>
    <message>
        <source>&amp;Redo</source>
        <translation>&amp;Rehacer</translation>
    </message>
    <message>
        <source>The computer could not keep up: simulated time was skipped</source>
        <translation>El ordenador no pudo seguir el ritmo: se saltó tiempo simulado</translation>
    </message>
    <message>
        <source>Simulated time</source>
        <translation>Tiempo simulado</translation>
    </message>
    <message>
        <source>Simulated seconds per real second ([ slower, ] faster)</source>
        <translation>Segundos simulados por segundo real ([ más lento, ] más rápido)</translation>
    </message>
    <message>
        <source>Frames drawn per second, and the time to draw one</source>
        <translation>Fotogramas dibujados por segundo y el tiempo de dibujar uno</translation>
    </message>
    <message>
        <source>Wall-clock time of the last simulation step</source>
        <translation>Tiempo real del último paso de la simulación</translation>
    </message>
    <message>
        <source>Number of balls</source>
        <translation>Número de bolas</translation>
    </message>
    <message>
        <source>Ball pairs tested for contact in the last step, and the contacts found</source>
        <translation>Pares de bolas probados en el último paso y contactos encontrados</translation>
    </message>
    <message>
        <source>%1: %2: %3</source>
        <translation>%1: %2: %3</translation>
    </message>
    <message>
        <source>not a saved window geometry; using the default size</source>
        <translation>no es una geometría de ventana guardada; se usa el tamaño por defecto</translation>
    </message>
    <message>
        <source>not a saved layout of the docks; using the default layout</source>
        <translation>no es una disposición de paneles guardada; se usa la disposición por defecto</translation>
    </message>
    <message>
        <source>%1 is not a folder; using the home folder</source>
        <translation>%1 no es una carpeta; se usa la carpeta personal</translation>
    </message>
    <message>
        <source>not true or false; using the plain theme</source>
        <translation>no es true ni false; se usa el tema normal</translation>
    </message>
    <message>
        <source>not a text size from %1 to %2; using the usual size</source>
        <translation>no es un tamaño de texto de %1 a %2; se usa el tamaño habitual</translation>
    </message>
    <message>
        <source>%1: %2: %3; opened the first lesson instead</source>
        <translation>%1: %2: %3; se abrió la primera lección en su lugar</translation>
    </message>
    <message>
        <source>no built-in lessons were found</source>
        <translation>no se encontraron lecciones incluidas</translation>
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
        <translation>Ya es la velocidad más lenta, %1×</translation>
    </message>
    <message>
        <source>Already the fastest speed, %1×</source>
        <translation>Ya es la velocidad más rápida, %1×</translation>
    </message>
    <message>
        <source>Speed %1×</source>
        <translation>Velocidad %1×</translation>
    </message>
    <message>
        <source>Cannot open lesson</source>
        <translation>No se puede abrir la lección</translation>
    </message>
    <message>
        <source>The lesson could not be opened; the running lesson goes on.</source>
        <translation>No se pudo abrir la lección; la lección en curso continúa.</translation>
    </message>
    <message numerus="yes">
        <source>… and %n more. Show Details… lists every problem.</source>
        <translation>
            <numerusform>… y %n más. Mostrar detalles… enumera todos los problemas.</numerusform>
            <numerusform>… y %n más. Mostrar detalles… enumera todos los problemas.</numerusform>
        </translation>
    </message>
    <message>
        <source>%1 %2</source>
        <translation>%1 %2</translation>
    </message>
    <message>
        <source>Text at %1% of its usual size (Ctrl+= larger, Ctrl+− smaller, Ctrl+0 usual)</source>
        <translation>Texto al %1 % de su tamaño habitual (Ctrl+= más grande, Ctrl+− más pequeño, Ctrl+0 habitual)</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source>speed %1×</source>
        <translation>velocidad %1×</translation>
    </message>
    <message>
        <source>%1 fps · draw %2 ms</source>
        <translation>%1 fps · dibujo %2 ms</translation>
    </message>
    <message>
        <source>step %1 µs</source>
        <translation>paso %1 µs</translation>
    </message>
    <message>
        <source>1 ball</source>
        <translation>1 bola</translation>
    </message>
    <message>
        <source>%L1 balls</source>
        <translation>%L1 bolas</translation>
    </message>
    <message>
        <source>pairs tested %L1 · contacts %L2</source>
        <translation>pares probados %L1 · contactos %L2</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pausa</translation>
    </message>
    <message>
        <source>&amp;Play</source>
        <translation>&amp;Ejecutar</translation>
    </message>
    <message>
        <source>Pause the simulation (Space)</source>
        <translation>Pausar la simulación (Espacio)</translation>
    </message>
    <message>
        <source>Run the simulation (Space)</source>
        <translation>Ejecutar la simulación (Espacio)</translation>
    </message>
    <message>
        <source>⚠ %1</source>
        <translation>⚠ %1</translation>
    </message>
    <message>
        <source>behind: %1 ms skipped</source>
        <translation>con retraso: %1 ms saltados</translation>
    </message>
    <message>
        <source>About ForceLab</source>
        <translation>Acerca de ForceLab</translation>
    </message>
    <message>
        <source>&lt;b&gt;ForceLab&lt;/b&gt; %1&lt;br&gt;A workbench for forces and collisions of balls in two dimensions.</source>
        <translation>&lt;b&gt;ForceLab&lt;/b&gt; %1&lt;br&gt;Un banco de trabajo de fuerzas y choques de bolas en dos dimensiones.</translation>
    </message>
    <message>
        <source>Step &amp;Back</source>
        <translation>Paso &amp;atrás</translation>
    </message>
    <message>
        <source>Pause and go back by one time step dt, to the world as it was (← or ,)</source>
        <translation>Pausa y retrocede un paso de tiempo dt, al mundo tal como era (← o ,)</translation>
    </message>
    <message>
        <source>Timeline</source>
        <translation>Línea de tiempo</translation>
    </message>
    <message>
        <source>&amp;Step</source>
        <translation>&amp;Paso</translation>
    </message>
    <message>
        <source>Pause and advance by one time step dt (→ or .)</source>
        <translation>Pausa y avanza un paso de tiempo dt (→ o .)</translation>
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
        <translation>&amp;Reiniciar</translation>
    </message>
    <message>
        <source>Reset</source>
        <comment>the word under the button&apos;s icon: short, it has 72 px on the stage</comment>
        <translation>Reinicio</translation>
    </message>
    <message>
        <source>Start the lesson again with its own values (R)</source>
        <translation>Empezar de nuevo la lección con sus propios valores (R)</translation>
    </message>
    <message>
        <source>S&amp;lower</source>
        <translation>Más &amp;lento</translation>
    </message>
    <message>
        <source>Slower</source>
        <comment>the word under the button&apos;s icon: short, it has 72 px on the stage</comment>
        <translation>Lento</translation>
    </message>
    <message>
        <source>Half the speed: slow motion down to 1/16× ([)</source>
        <translation>La mitad de velocidad: cámara lenta hasta 1/16× ([)</translation>
    </message>
    <message>
        <source>&amp;Faster</source>
        <translation>Más &amp;rápido</translation>
    </message>
    <message>
        <source>Faster</source>
        <comment>the word under the button&apos;s icon: short, it has 72 px on the stage</comment>
        <translation>Rápido</translation>
    </message>
    <message>
        <source>Double the speed, up to %1× (])</source>
        <translation>El doble de velocidad, hasta %1× (])</translation>
    </message>
    <message>
        <source>&amp;Add Ball</source>
        <translation>&amp;Añadir bola</translation>
    </message>
    <message>
        <source>Add a ball in the middle of the box (B). Right-click the stage to add one where you click.</source>
        <translation>Añade una bola en el centro de la caja (B). Clic derecho en el escenario para añadirla donde hagas clic.</translation>
    </message>
    <message>
        <source>&amp;Delete Ball</source>
        <translation>&amp;Borrar bola</translation>
    </message>
    <message>
        <source>D&amp;uplicate Ball</source>
        <translation>D&amp;uplicar bola</translation>
    </message>
    <message>
        <source>&amp;Copy Ball</source>
        <translation>&amp;Copiar bola</translation>
    </message>
    <message>
        <source>&amp;Paste Ball</source>
        <translation>&amp;Pegar bola</translation>
    </message>
    <message>
        <source>Zoom &amp;In</source>
        <translation>&amp;Acercar</translation>
    </message>
    <message>
        <source>Zoom in on the middle (+); the mouse wheel zooms in on the pointer</source>
        <translation>Acercar el centro (+); la rueda del ratón acerca hacia el puntero</translation>
    </message>
    <message>
        <source>Zoom &amp;Out</source>
        <translation>&amp;Alejar</translation>
    </message>
    <message>
        <source>Zoom out (−), to see balls that left the box</source>
        <translation>Alejar (−), para ver las bolas que salieron de la caja</translation>
    </message>
    <message>
        <source>Fit the &amp;Box</source>
        <translation>Ajustar a la &amp;caja</translation>
    </message>
    <message>
        <source>Show the whole box, as large as it fits (0)</source>
        <translation>Muestra toda la caja, tan grande como quepa (0)</translation>
    </message>
    <message>
        <source>Fit &amp;All Balls</source>
        <translation>Ajustar a &amp;todas las bolas</translation>
    </message>
    <message>
        <source>Zoom so that every ball is seen, in the box or out of it (A)</source>
        <translation>Ajusta el zoom para ver todas las bolas, dentro o fuera de la caja (A)</translation>
    </message>
    <message>
        <source>&amp;Follow the Selected Ball</source>
        <translation>&amp;Seguir la bola seleccionada</translation>
    </message>
    <message>
        <source>Keep the selected ball in the middle of the view as it moves (F)</source>
        <translation>Mantiene la bola seleccionada en el centro de la vista mientras se mueve (F)</translation>
    </message>
    <message>
        <source>&amp;Open Lesson…</source>
        <translation>&amp;Abrir lección…</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>Abrir</translation>
    </message>
    <message>
        <source>Open a lesson file from disk</source>
        <translation>Abrir un archivo de lección del disco</translation>
    </message>
    <message>
        <source>&amp;Save Scene as Lesson…</source>
        <translation>&amp;Guardar la escena como lección…</translation>
    </message>
    <message>
        <source>Save</source>
        <translation>Guardar</translation>
    </message>
    <message>
        <source>Save the balls as they are now and the live settings as a lesson file</source>
        <translation>Guarda las bolas tal como están y los ajustes actuales como archivo de lección</translation>
    </message>
    <message>
        <source>Screens&amp;hot…</source>
        <translation>&amp;Captura…</translation>
    </message>
    <message>
        <source>Picture</source>
        <translation>Imagen</translation>
    </message>
    <message>
        <source>Save a picture of the canvas as PNG</source>
        <translation>Guardar una imagen del lienzo en PNG</translation>
    </message>
    <message>
        <source>Re&amp;cord Trajectory</source>
        <translation>&amp;Grabar trayectoria</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Grabar</translation>
    </message>
    <message>
        <source>Record the path of the selected ball (or of all balls when none is selected)</source>
        <translation>Graba la trayectoria de la bola seleccionada (o de todas si no hay ninguna seleccionada)</translation>
    </message>
    <message>
        <source>Recording ball #%1</source>
        <translation>Grabando la bola n.º %1</translation>
    </message>
    <message>
        <source>Recording every ball</source>
        <translation>Grabando todas las bolas</translation>
    </message>
    <message>
        <source>&amp;Export Trajectory…</source>
        <translation>&amp;Exportar trayectoria…</translation>
    </message>
    <message>
        <source>CSV</source>
        <translation>CSV</translation>
    </message>
    <message>
        <source>Write the recorded trajectory as CSV (time, ball, position, velocity)</source>
        <translation>Escribe la trayectoria grabada en CSV (tiempo, bola, posición, velocidad)</translation>
    </message>
    <message>
        <source>Export Teacher &amp;Handbook…</source>
        <translation>Exportar el &amp;manual del profesor…</translation>
    </message>
    <message>
        <source>Write every lesson with its teacher notes as one printable HTML page</source>
        <translation>Escribe todas las lecciones con sus notas del profesor en una página HTML imprimible</translation>
    </message>
    <message>
        <source>&amp;Previous Lesson</source>
        <translation>Lección &amp;anterior</translation>
    </message>
    <message>
        <source>&amp;Next Lesson</source>
        <translation>Lección &amp;siguiente</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;Stage View (Projector)</source>
        <translation>Vista de &amp;escenario (proyector)</translation>
    </message>
    <message>
        <source>The simulation fills the screen with large controls beside it, for a projector (F11; Escape leaves)</source>
        <translation>La simulación llena la pantalla con controles grandes al lado, para un proyector (F11; Escape sale)</translation>
    </message>
    <message>
        <source>Stage</source>
        <translation>Escenario</translation>
    </message>
    <message>
        <source>&amp;Larger Text</source>
        <translation>Texto más &amp;grande</translation>
    </message>
    <message>
        <source>Larger text in every panel and on the stage (Ctrl+=)</source>
        <translation>Texto más grande en todos los paneles y en el escenario (Ctrl+=)</translation>
    </message>
    <message>
        <source>S&amp;maller Text</source>
        <translation>Texto más &amp;pequeño</translation>
    </message>
    <message>
        <source>Smaller text in every panel and on the stage (Ctrl+−)</source>
        <translation>Texto más pequeño en todos los paneles y en el escenario (Ctrl+−)</translation>
    </message>
    <message>
        <source>&amp;Usual Text Size</source>
        <translation>Tamaño de texto &amp;habitual</translation>
    </message>
    <message>
        <source>P&amp;rojector Theme</source>
        <translation>Tema de p&amp;royector</translation>
    </message>
    <message>
        <source>White box, dark thick outlines, colour-blind-safe balls and larger text everywhere (always on in the stage view)</source>
        <translation>Caja blanca, contornos gruesos oscuros, bolas aptas para daltónicos y texto más grande en todas partes (siempre activo en la vista de escenario)</translation>
    </message>
    <message>
        <source>Picture at &amp;Double Size…</source>
        <translation>Imagen a tamaño &amp;doble…</translation>
    </message>
    <message>
        <source>Save the stage at twice the screen&apos;s resolution, for print</source>
        <translation>Guarda el escenario al doble de la resolución de la pantalla, para imprimir</translation>
    </message>
    <message>
        <source>&amp;About ForceLab</source>
        <translation>&amp;Acerca de ForceLab</translation>
    </message>
    <message>
        <source>&amp;Pixels</source>
        <translation>&amp;Píxeles</translation>
    </message>
    <message>
        <source>Show px, px/s and mass units, as the program computes them</source>
        <translation>Muestra px, px/s y unidades de masa, tal como calcula el programa</translation>
    </message>
    <message>
        <source>&amp;SI (m, kg, N, J)</source>
        <translation>&amp;SI (m, kg, N, J)</translation>
    </message>
    <message>
        <source>Show metres, kilograms, newtons and joules at the scale set below</source>
        <translation>Muestra metros, kilogramos, newtons y julios a la escala fijada abajo</translation>
    </message>
    <message>
        <source>How many pixels make a metre, and how many kilograms a mass unit</source>
        <translation>Cuántos píxeles forman un metro y cuántos kilogramos una unidad de masa</translation>
    </message>
    <message>
        <source>SI Scale</source>
        <translation>Escala SI</translation>
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
        <translation>1 m son</translation>
    </message>
    <message>
        <source>1 mass unit is</source>
        <translation>1 unidad de masa son</translation>
    </message>
    <message>
        <source>SI &amp;Scale: %1 px = 1 m, 1 mass unit = %2 kg…</source>
        <translation>&amp;Escala SI: %1 px = 1 m, 1 unidad de masa = %2 kg…</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>&amp;Edit</source>
        <translation>&amp;Editar</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulación</translation>
    </message>
    <message>
        <source>&amp;Lesson</source>
        <translation>&amp;Lección</translation>
    </message>
    <message>
        <source>&amp;Tools</source>
        <translation>&amp;Herramientas</translation>
    </message>
    <message>
        <source>&amp;Accuracy</source>
        <translation>&amp;Precisión</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <source>&amp;Units</source>
        <translation>&amp;Unidades</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>A&amp;yuda</translation>
    </message>
    <message>
        <source>Simulation</source>
        <translation>Simulación</translation>
    </message>
    <message>
        <source>Show</source>
        <translation>Mostrar</translation>
    </message>
    <message>
        <source>Show: what the stage draws</source>
        <translation>Mostrar: lo que dibuja el escenario</translation>
    </message>
    <message>
        <source>File</source>
        <translation>Archivo</translation>
    </message>
    <message>
        <source>Open Lesson</source>
        <translation>Abrir lección</translation>
    </message>
    <message>
        <source>Lesson files (*.json);;All files (*)</source>
        <translation>Archivos de lección (*.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Lesson not saved: %1</source>
        <translation>Lección no guardada: %1</translation>
    </message>
    <message numerus="yes">
        <source>Saved %n ball(s) and the settings to %1 as “%2”. %3</source>
        <translation>
            <numerusform>Guardada %n bola y los ajustes en %1 como «%2». %3</numerusform>
            <numerusform>Guardadas %n bolas y los ajustes en %1 como «%2». %3</numerusform>
        </translation>
    </message>
    <message>
        <source>Picture not saved: %1</source>
        <translation>Imagen no guardada: %1</translation>
    </message>
    <message>
        <source>Saved the picture to %1</source>
        <translation>Imagen guardada en %1</translation>
    </message>
    <message>
        <source>Save Picture at Double Size</source>
        <translation>Guardar la imagen a tamaño doble</translation>
    </message>
    <message>
        <source>Save Picture</source>
        <translation>Guardar la imagen</translation>
    </message>
    <message>
        <source>PNG images (*.png)</source>
        <translation>Imágenes PNG (*.png)</translation>
    </message>
    <message>
        <source>Export Teacher Handbook</source>
        <translation>Exportar el manual del profesor</translation>
    </message>
    <message>
        <source>HTML (*.html)</source>
        <translation>HTML (*.html)</translation>
    </message>
    <message>
        <source>%1
The handbook was not written; an old file there is unchanged.</source>
        <translation>%1
No se escribió el manual; el archivo antiguo que había sigue igual.</translation>
    </message>
    <message>
        <source>Handbook written to %1</source>
        <translation>Manual escrito en %1</translation>
    </message>
    <message>
        <source>Nothing recorded yet: switch on Record Trajectory (Ctrl+Shift+R) first</source>
        <translation>Aún no se ha grabado nada: activa primero Grabar trayectoria (Ctrl+Shift+R)</translation>
    </message>
    <message>
        <source>Export Trajectory</source>
        <translation>Exportar trayectoria</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Archivos CSV (*.csv)</translation>
    </message>
    <message>
        <source>Wrote %L1 rows to %2</source>
        <translation>%L1 filas escritas en %2</translation>
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
        <translation>&amp;Mostrar</translation>
    </message>
    <message>
        <source>&amp;Velocity arrows</source>
        <translation>Flechas de &amp;velocidad</translation>
    </message>
    <message>
        <source>&amp;Acceleration arrows (a = F/m)</source>
        <translation>Flechas de &amp;aceleración (a = F/m)</translation>
    </message>
    <message>
        <source>&amp;Force arrows (net force F = m a)</source>
        <translation>Flechas de &amp;fuerza (fuerza neta F = m a)</translation>
    </message>
    <message>
        <source>Forces &amp;by source (one arrow per force)</source>
        <translation>Fuerzas por &amp;origen (una flecha por fuerza)</translation>
    </message>
    <message>
        <source>&amp;Paths</source>
        <translation>&amp;Trayectorias</translation>
    </message>
    <message>
        <source>&amp;Centre of mass and its path</source>
        <translation>&amp;Centro de masas y su trayectoria</translation>
    </message>
    <message>
        <source>M&amp;omenta diagram (p = m v, tip to tail)</source>
        <translation>Diagrama de m&amp;omentos (p = m v, uno tras otro)</translation>
    </message>
    <message>
        <source>Tops of the flights, with their &amp;heights</source>
        <translation>Puntos más altos de los vuelos, con sus &amp;alturas</translation>
    </message>
    <message>
        <source>&amp;Readout of the selected ball</source>
        <translation>&amp;Valores de la bola seleccionada</translation>
    </message>
    <message>
        <source>&amp;Totals: energy and momentum</source>
        <translation>&amp;Totales: energía y momento</translation>
    </message>
    <message>
        <source>&amp;Mark touching balls</source>
        <translation>&amp;Marcar las bolas que se tocan</translation>
    </message>
    <message>
        <source>&amp;Grid</source>
        <translation>&amp;Cuadrícula</translation>
    </message>
    <message>
        <source>&amp;Markers (centres, anchors, homes)</source>
        <translation>Ma&amp;rcas (centros, anclajes, casas)</translation>
    </message>
    <message>
        <source>Arrow &amp;length</source>
        <translation>&amp;Longitud de las flechas</translation>
    </message>
    <message>
        <source>&amp;Auto: readable (about 45 px)</source>
        <translation>&amp;Automática: legible (unos 45 px)</translation>
    </message>
    <message>
        <source>The lesson&apos;s scale (×1)</source>
        <translation>La escala de la lección (×1)</translation>
    </message>
    <message>
        <source>×%1 the lesson&apos;s scale</source>
        <translation>×%1 la escala de la lección</translation>
    </message>
    <message>
        <source>Arrow scale ×&amp;2</source>
        <translation>Escala de flechas ×&amp;2</translation>
    </message>
    <message>
        <source>Arrow scale ÷2</source>
        <translation>Escala de flechas ÷2</translation>
    </message>
    <message>
        <source>Arrow scale &amp;from now</source>
        <translation>Escala de flechas &amp;desde ahora</translation>
    </message>
</context>
<context>
    <name>forcelab::ParameterPanel</name>
    <message>
        <source>Show all parameters</source>
        <translation>Mostrar todos los parámetros</translation>
    </message>
    <message>
        <source>Besides the lesson&apos;s own controls, show every setting of the world</source>
        <translation>Además de los controles de la lección, muestra todos los ajustes del mundo</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>Gravedad</translation>
    </message>
    <message>
        <source>Box and walls</source>
        <translation>Caja y paredes</translation>
    </message>
    <message>
        <source>Drag</source>
        <translation>Rozamiento del aire</translation>
    </message>
    <message>
        <source>Wind</source>
        <translation>Viento</translation>
    </message>
    <message>
        <source>Random acceleration</source>
        <translation>Aceleración aleatoria</translation>
    </message>
    <message>
        <source>Point force</source>
        <translation>Fuerza de un punto</translation>
    </message>
    <message>
        <source>Spring</source>
        <translation>Muelle</translation>
    </message>
    <message>
        <source>Gravity between balls</source>
        <translation>Gravedad entre bolas</translation>
    </message>
    <message>
        <source>Homing</source>
        <translation>Regreso a casa</translation>
    </message>
    <message>
        <source>Pointer force</source>
        <translation>Fuerza del puntero</translation>
    </message>
    <message>
        <source>Speed limit</source>
        <translation>Límite de rapidez</translation>
    </message>
    <message>
        <source>Collisions</source>
        <translation>Choques</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Tiempo</translation>
    </message>
    <message>
        <source>Balls</source>
        <translation>Bolas</translation>
    </message>
    <message numerus="yes">
        <source>%n more setting(s) under &quot;Show all parameters&quot;.</source>
        <translation>
            <numerusform>%n ajuste más en «Mostrar todos los parámetros».</numerusform>
            <numerusform>%n ajustes más en «Mostrar todos los parámetros».</numerusform>
        </translation>
    </message>
    <message>
        <source>Change %1</source>
        <translation>Cambiar %1</translation>
    </message>
    <message>
        <source>Tick to switch %1 on</source>
        <translation>Marca para activar %1</translation>
    </message>
    <message>
        <source>%1 to %2%3</source>
        <translation>%1 a %2%3</translation>
    </message>
    <message>
        <source>left</source>
        <translation>izquierda</translation>
    </message>
    <message>
        <source>right</source>
        <translation>derecha</translation>
    </message>
    <message>
        <source>top</source>
        <translation>arriba</translation>
    </message>
    <message>
        <source>bottom</source>
        <translation>abajo</translation>
    </message>
    <message>
        <source>Walls</source>
        <translation>Paredes</translation>
    </message>
    <message>
        <source>A wall that is not ticked is open</source>
        <translation>Una pared sin marcar está abierta</translation>
    </message>
    <message>
        <source>time.seed: &quot;%1&quot; is not a whole number from 0 to 18446744073709551615</source>
        <translation>time.seed: «%1» no es un número entero de 0 a 18446744073709551615</translation>
    </message>
    <message>
        <source>Seed</source>
        <translation>Semilla</translation>
    </message>
    <message>
        <source>Random numbers (wind, random acceleration) start from this seed when the balls are placed again</source>
        <translation>Los números aleatorios (viento, aceleración aleatoria) empiezan desde esta semilla cuando se vuelven a colocar las bolas</translation>
    </message>
    <message numerus="yes">
        <source>Place %n random ball(s)</source>
        <translation>
            <numerusform>Colocar %n bola aleatoria</numerusform>
            <numerusform>Colocar %n bolas aleatorias</numerusform>
        </translation>
    </message>
    <message>
        <source>Place random balls</source>
        <translation>Colocar bolas aleatorias</translation>
    </message>
    <message>
        <source>Random balls</source>
        <translation>Bolas aleatorias</translation>
    </message>
    <message>
        <source>How many balls are placed at random (besides the lesson&apos;s own); changing it starts again</source>
        <translation>Cuántas bolas se colocan al azar (además de las de la lección); cambiarlo empieza de nuevo</translation>
    </message>
    <message>
        <source>Slowest random ball</source>
        <translation>Bola aleatoria más lenta</translation>
    </message>
    <message>
        <source>Fastest random ball</source>
        <translation>Bola aleatoria más rápida</translation>
    </message>
    <message>
        <source>Random balls start with a speed of at least this; changing it starts again</source>
        <translation>Las bolas aleatorias empiezan con al menos esta rapidez; cambiarlo empieza de nuevo</translation>
    </message>
    <message>
        <source>Random balls start with a speed of at most this; changing it starts again</source>
        <translation>Las bolas aleatorias empiezan con como mucho esta rapidez; cambiarlo empieza de nuevo</translation>
    </message>
    <message>
        <source>Place balls fully inside</source>
        <translation>Colocar las bolas del todo dentro</translation>
    </message>
    <message>
        <source>Let balls start partly outside</source>
        <translation>Dejar que las bolas empiecen en parte fuera</translation>
    </message>
    <message>
        <source>Start fully inside</source>
        <translation>Empezar del todo dentro</translation>
    </message>
    <message>
        <source>Off: a ball&apos;s centre may be anywhere in the box, so it can start partly outside a wall (stage 4&apos;s bug). Changing it places the balls again</source>
        <translation>Desactivado: el centro de una bola puede estar en cualquier punto de la caja, así que puede empezar en parte fuera de una pared (el error de la etapa 4). Cambiarlo vuelve a colocar las bolas</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Velocidad</translation>
    </message>
    <message>
        <source>Simulated seconds per real second: below 1 is slow motion (%1× to %2×)</source>
        <translation>Segundos simulados por segundo real: por debajo de 1 es cámara lenta (de %1× a %2×)</translation>
    </message>
</context>
<context>
    <name>forcelab::PlotsDock</name>
    <message>
        <source>Plots</source>
        <translation>Gráficas</translation>
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
        <translation>un paso</translation>
    </message>
    <message>
        <source>Plots of energy, momentum and step cost</source>
        <translation>Gráficas de energía, momento y coste por paso</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energía</translation>
    </message>
    <message>
        <source>Energy bars</source>
        <translation>Barras de energía</translation>
    </message>
    <message>
        <source>Graph</source>
        <translation>Gráfica</translation>
    </message>
    <message>
        <source>Momentum</source>
        <translation>Momento</translation>
    </message>
    <message>
        <source>Cost of a step</source>
        <translation>Coste de un paso</translation>
    </message>
    <message>
        <source>Step cost</source>
        <translation>Coste por paso</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tiempo (s)</translation>
    </message>
    <message>
        <source>Momentum (×10¹² mass·px²/s²)</source>
        <translation>Momento (×10¹² masa·px²/s²)</translation>
    </message>
    <message>
        <source>Speeds</source>
        <translation>Rapideces</translation>
    </message>
    <message>
        <source>Computer time per step</source>
        <translation>Tiempo de cálculo por paso</translation>
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
        <translation>Predicción</translation>
    </message>
    <message>
        <source>Your prediction</source>
        <translation>Tu predicción</translation>
    </message>
    <message>
        <source>your guess</source>
        <translation>tu estimación</translation>
    </message>
    <message>
        <source>Lock in and run</source>
        <translation>Fijar y ejecutar</translation>
    </message>
    <message>
        <source>Show the answer now</source>
        <translation>Mostrar la respuesta ya</translation>
    </message>
    <message>
        <source>Next question</source>
        <translation>Siguiente pregunta</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>This lesson asks no question before it runs.</source>
        <translation>Esta lección no hace ninguna pregunta antes de ejecutarse.</translation>
    </message>
    <message>
        <source>Make your prediction while the lesson waits at t = 0, then run it.</source>
        <translation>Haz tu predicción mientras la lección espera en t = 0 y luego ejecútala.</translation>
    </message>
    <message>
        <source>Type a number first (for example 200).</source>
        <translation>Escribe primero un número (por ejemplo 200).</translation>
    </message>
    <message>
        <source>Pick an answer first.</source>
        <translation>Elige primero una respuesta.</translation>
    </message>
    <message>
        <source>Still stopping the last measurement; try again in a moment.</source>
        <translation>Todavía se está parando la última medición; vuelve a intentarlo en un momento.</translation>
    </message>
    <message>
        <source>Locked in. Working out the answer…</source>
        <translation>Fijada. Calculando la respuesta…</translation>
    </message>
    <message>
        <source>Cancelled. Change your answer or lock it in again.</source>
        <translation>Cancelado. Cambia tu respuesta o vuelve a fijarla.</translation>
    </message>
    <message>
        <source>Locked in. Watch: the answer comes at t = %1 s.</source>
        <translation>Fijada. Atento: la respuesta llega en t = %1 s.</translation>
    </message>
    <message>
        <source>It could not be measured in this run (the lesson&apos;s sentence “%1”). Did a setting change it?</source>
        <translation>No se pudo medir en esta ejecución (la frase de la lección «%1»). ¿La ha cambiado algún ajuste?</translation>
    </message>
    <message>
        <source>You chose &lt;b&gt;%1&lt;/b&gt;. Measured: &lt;b&gt;%2 %3&lt;/b&gt;, so the answer is &lt;b&gt;%4&lt;/b&gt;. %5</source>
        <translation>Elegiste &lt;b&gt;%1&lt;/b&gt;. Medido: &lt;b&gt;%2 %3&lt;/b&gt;, así que la respuesta es &lt;b&gt;%4&lt;/b&gt;. %5</translation>
    </message>
    <message>
        <source>Well predicted!</source>
        <translation>¡Bien predicho!</translation>
    </message>
    <message>
        <source>Why was it different?</source>
        <translation>¿Por qué ha sido distinto?</translation>
    </message>
    <message>
        <source> (%1%)</source>
        <translation> (%1 %)</translation>
    </message>
    <message>
        <source>You said &lt;b&gt;%1 %2&lt;/b&gt;. Measured: &lt;b&gt;%3 %2&lt;/b&gt;. You were %4 %2 off%5.</source>
        <translation>Dijiste &lt;b&gt;%1 %2&lt;/b&gt;. Medido: &lt;b&gt;%3 %2&lt;/b&gt;. Te equivocaste en %4 %2%5.</translation>
    </message>
    <message>
        <source>&lt;br&gt;&lt;small&gt;The run measured what the lesson says: “%1”.&lt;/small&gt;</source>
        <translation>&lt;br&gt;&lt;small&gt;La ejecución midió lo que dice la lección: «%1».&lt;/small&gt;</translation>
    </message>
</context>
<context>
    <name>forcelab::QuantityGraph</name>
    <message>
        <source>x position</source>
        <translation>posición x</translation>
    </message>
    <message>
        <source>y position</source>
        <translation>posición y</translation>
    </message>
    <message>
        <source>velocity v_x</source>
        <translation>velocidad v_x</translation>
    </message>
    <message>
        <source>velocity v_y</source>
        <translation>velocidad v_y</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>rapidez</translation>
    </message>
    <message>
        <source>kinetic energy</source>
        <translation>energía cinética</translation>
    </message>
    <message>
        <source>potential energy</source>
        <translation>energía potencial</translation>
    </message>
    <message>
        <source>total energy</source>
        <translation>energía total</translation>
    </message>
    <message>
        <source>momentum p_x</source>
        <translation>momento p_x</translation>
    </message>
    <message>
        <source>momentum p_y</source>
        <translation>momento p_y</translation>
    </message>
    <message>
        <source>Quantity to graph</source>
        <translation>Magnitud que representar</translation>
    </message>
    <message>
        <source>Ball to graph</source>
        <translation>Bola que representar</translation>
    </message>
    <message>
        <source>of</source>
        <translation>de</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>medido</translation>
    </message>
    <message>
        <source>time (s)</source>
        <translation>tiempo (s)</translation>
    </message>
    <message>
        <source>all balls</source>
        <translation>todas las bolas</translation>
    </message>
    <message>
        <source>ball %1</source>
        <translation>bola %1</translation>
    </message>
    <message>
        <source>theory: E₀, nothing takes energy away</source>
        <translation>teoría: E₀, nada quita energía</translation>
    </message>
    <message>
        <source>theory: x₀ + v₀t + ½gt²</source>
        <translation>teoría: x₀ + v₀t + ½gt²</translation>
    </message>
    <message>
        <source>theory: x₀ + v₀t</source>
        <translation>teoría: x₀ + v₀t</translation>
    </message>
    <message>
        <source>theory: y₀ + v₀t + ½gt²</source>
        <translation>teoría: y₀ + v₀t + ½gt²</translation>
    </message>
    <message>
        <source>theory: y₀ + v₀t</source>
        <translation>teoría: y₀ + v₀t</translation>
    </message>
    <message>
        <source>theory: v₀ + gt</source>
        <translation>teoría: v₀ + gt</translation>
    </message>
    <message>
        <source>theory: v₀, constant</source>
        <translation>teoría: v₀, constante</translation>
    </message>
    <message>
        <source>theory: |v₀ + gt|</source>
        <translation>teoría: |v₀ + gt|</translation>
    </message>
    <message>
        <source>theory: |v₀|, constant</source>
        <translation>teoría: |v₀|, constante</translation>
    </message>
    <message>
        <source>theory: ½m|v₀ + gt|²</source>
        <translation>teoría: ½m|v₀ + gt|²</translation>
    </message>
    <message>
        <source>theory: ½m|v₀|², constant</source>
        <translation>teoría: ½m|v₀|², constante</translation>
    </message>
    <message>
        <source>theory: mgh, h of the flight</source>
        <translation>teoría: mgh, h del vuelo</translation>
    </message>
    <message>
        <source>theory: 0, no gravity</source>
        <translation>teoría: 0, sin gravedad</translation>
    </message>
    <message>
        <source>theory: E₀, constant</source>
        <translation>teoría: E₀, constante</translation>
    </message>
    <message>
        <source>theory: m(v₀ + gt)</source>
        <translation>teoría: m(v₀ + gt)</translation>
    </message>
    <message>
        <source>theory: mv₀, constant</source>
        <translation>teoría: mv₀, constante</translation>
    </message>
    <message>
        <source>%1 of %2 (%3%4)</source>
        <translation>%1 de %2 (%3%4)</translation>
    </message>
</context>
<context>
    <name>forcelab::SaveLessonDialog</name>
    <message>
        <source>Save Scene as Lesson</source>
        <translation>Guardar la escena como lección</translation>
    </message>
    <message>
        <source>The scene is saved as a new lesson with your title and text. Of the claims and questions of “%1”, only those that still hold in this scene are kept; the others are listed after saving.</source>
        <translation>La escena se guarda como una lección nueva con tu título y tu texto. De las afirmaciones y preguntas de «%1» solo se conservan las que siguen siendo ciertas en esta escena; las demás se enumeran después de guardar.</translation>
    </message>
    <message>
        <source>Plain text; an empty line starts a new paragraph.</source>
        <translation>Texto sencillo; una línea vacía empieza un párrafo nuevo.</translation>
    </message>
    <message>
        <source>&amp;Keep the teacher notes</source>
        <translation>&amp;Conservar las notas del profesor</translation>
    </message>
    <message>
        <source>The goal, the minutes and the misconceptions. The answers to the challenges are never kept: the new lesson has no challenges.</source>
        <translation>El objetivo, los minutos y las ideas erróneas. Las respuestas a los retos nunca se conservan: la lección nueva no tiene retos.</translation>
    </message>
    <message>
        <source>C&amp;hoose…</source>
        <translation>&amp;Elegir…</translation>
    </message>
    <message>
        <source>&amp;Title:</source>
        <translation>&amp;Título:</translation>
    </message>
    <message>
        <source>Te&amp;xt:</source>
        <translation>Te&amp;xto:</translation>
    </message>
    <message>
        <source>&amp;File:</source>
        <translation>&amp;Archivo:</translation>
    </message>
    <message>
        <source>Lesson files (*.json)</source>
        <translation>Archivos de lección (*.json)</translation>
    </message>
    <message>
        <source>The lesson needs a title.</source>
        <translation>La lección necesita un título.</translation>
    </message>
    <message>
        <source>“%1” has a number or a comparison (“%2”) that nothing measures on this scene, and a lesson must not say what it does not check. Write it without, or add a claim to the file later.</source>
        <translation>«%1» tiene un número o una comparación («%2») que nada mide en esta escena, y una lección no debe decir lo que no comprueba. Escríbela sin él, o añade después una afirmación al archivo.</translation>
    </message>
    <message>
        <source>Choose the file to save to.</source>
        <translation>Elige el archivo donde guardar.</translation>
    </message>
</context>
<context>
    <name>forcelab::SettingsEditor</name>
    <message>
        <source>Random balls from %1 to %2 px/s</source>
        <translation>Bolas aleatorias de %1 a %2 px/s</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1: %2</translation>
    </message>
    <message>
        <source>mass: %1 is outside %2</source>
        <translation>masa: %1 está fuera de %2</translation>
    </message>
    <message>
        <source>Not placed: %1</source>
        <translation>No colocada: %1</translation>
    </message>
    <message>
        <source>Moved to (%1, %2) px, touching, so it does not overlap</source>
        <translation>Movida a (%1, %2) px, tocando, para que no se solape</translation>
    </message>
    <message>
        <source>Not added: the world holds at most %1 balls</source>
        <translation>No añadida: el mundo admite como mucho %1 bolas</translation>
    </message>
    <message>
        <source>Delete ball %1</source>
        <translation>Borrar la bola %1</translation>
    </message>
    <message>
        <source>Duplicate ball %1</source>
        <translation>Duplicar la bola %1</translation>
    </message>
</context>
<context>
    <name>forcelab::SimulationController</name>
    <message>
        <source>%1 pane: %2</source>
        <translation>panel %1: %2</translation>
    </message>
    <message>
        <source>your code</source>
        <translation>tu código</translation>
    </message>
    <message>
        <source>spawn.count: %1 listed + %2 random balls is more than the limit of %3</source>
        <translation>spawn.count: %1 bolas de la lista + %2 aleatorias superan el límite de %3</translation>
    </message>
    <message>
        <source>time scale: %1 is outside %2 to %3</source>
        <translation>escala de tiempo: %1 está fuera de %2 a %3</translation>
    </message>
    <message>
        <source>ghost: %1</source>
        <translation>fantasma: %1</translation>
    </message>
</context>
<context>
    <name>forcelab::SpeedHistogram</name>
    <message>
        <source>Histogram of the balls&apos; speeds with the Maxwell–Boltzmann curve</source>
        <translation>Histograma de las rapideces de las bolas con la curva de Maxwell-Boltzmann</translation>
    </message>
    <message>
        <source>balls</source>
        <translation>bolas</translation>
    </message>
    <message>
        <source>Maxwell–Boltzmann (2D), same energy</source>
        <translation>Maxwell-Boltzmann (2D), misma energía</translation>
    </message>
    <message>
        <source>speed (px/s)</source>
        <translation>rapidez (px/s)</translation>
    </message>
    <message>
        <source>speed (%1)</source>
        <translation>rapidez (%1)</translation>
    </message>
    <message>
        <source>%1balls per %2 %3</source>
        <translation>%1bolas por %2 %3</translation>
    </message>
    <message>
        <source>Speeds of %1</source>
        <translation>Rapideces de %1</translation>
    </message>
    <message>
        <source>ball</source>
        <translation>bola</translation>
    </message>
</context>
<context>
    <name>forcelab::StageSliders</name>
    <message>
        <source>Left</source>
        <translation>Izquierda</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Derecha</translation>
    </message>
    <message>
        <source>Top</source>
        <translation>Arriba</translation>
    </message>
    <message>
        <source>Bottom</source>
        <translation>Abajo</translation>
    </message>
    <message>
        <source>A wall whose button is not pressed is open: a ball leaves through it</source>
        <translation>Una pared cuyo botón no está pulsado está abierta: una bola sale por ella</translation>
    </message>
    <message>
        <source>Off: a ball&apos;s centre may be anywhere in the box, so it can start partly outside a wall. Changing it places the balls again</source>
        <translation>Desactivado: el centro de una bola puede estar en cualquier punto de la caja, así que puede empezar en parte fuera de una pared. Cambiarlo vuelve a colocar las bolas</translation>
    </message>
    <message>
        <source>Place balls fully inside</source>
        <translation>Colocar las bolas del todo dentro</translation>
    </message>
    <message>
        <source>Let balls start partly outside</source>
        <translation>Dejar que las bolas empiecen en parte fuera</translation>
    </message>
    <message>
        <source>Slowest random ball</source>
        <translation>Bola aleatoria más lenta</translation>
    </message>
    <message>
        <source>Fastest random ball</source>
        <translation>Bola aleatoria más rápida</translation>
    </message>
    <message>
        <source>Walls: &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>Paredes: &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguna</translation>
    </message>
    <message>
        <source>Slowest random ball: &lt;b&gt;%1&lt;/b&gt; %2</source>
        <translation>Bola aleatoria más lenta: &lt;b&gt;%1&lt;/b&gt; %2</translation>
    </message>
    <message>
        <source>Fastest random ball: &lt;b&gt;%1&lt;/b&gt; %2</source>
        <translation>Bola aleatoria más rápida: &lt;b&gt;%1&lt;/b&gt; %2</translation>
    </message>
    <message>
        <source>Switch off</source>
        <translation>Desactivar</translation>
    </message>
    <message>
        <source>Switch on</source>
        <translation>Activar</translation>
    </message>
    <message>
        <source>Start fully inside: &lt;b&gt;%1&lt;/b&gt;</source>
        <translation>Empezar del todo dentro: &lt;b&gt;%1&lt;/b&gt;</translation>
    </message>
    <message>
        <source>on</source>
        <translation>sí</translation>
    </message>
    <message>
        <source>off</source>
        <translation>no</translation>
    </message>
</context>
<context>
    <name>forcelab::StageToolTitle</name>
    <message>
        <source>Close (the tool&apos;s key again)</source>
        <translation>Cerrar (otra vez la tecla de la herramienta)</translation>
    </message>
</context>
<context>
    <name>forcelab::StageView</name>
    <message>
        <source>Sliders</source>
        <translation>Mandos</translation>
    </message>
    <message>
        <source>Show the lesson&apos;s sliders under the box in the stage view (S)</source>
        <translation>Muestra los deslizadores de la lección bajo la caja en la vista de escenario (S)</translation>
    </message>
    <message>
        <source>Balls</source>
        <translation>Bolas</translation>
    </message>
    <message>
        <source>Show every ball&apos;s numbers under the box, to type new ones (T)</source>
        <translation>Muestra los números de cada bola bajo la caja, para escribir otros nuevos (T)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Stopped:&lt;/b&gt; %1</source>
        <translation>&lt;b&gt;Detenido:&lt;/b&gt; %1</translation>
    </message>
    <message>
        <source>t = %1 s   %2× speed</source>
        <translation>t = %1 s   velocidad %2×</translation>
    </message>
</context>
<context>
    <name>forcelab::StepApartDock</name>
    <message>
        <source>One Step Apart</source>
        <translation>Un paso por dentro</translation>
    </message>
    <message>
        <source>all</source>
        <translation>todos</translation>
    </message>
    <message>
        <source>Sub-step shown</source>
        <translation>Subpaso mostrado</translation>
    </message>
    <message>
        <source>Sub-step shown:</source>
        <translation>Subpaso mostrado:</translation>
    </message>
    <message>
        <source>◀ Step back</source>
        <translation>◀ Paso atrás</translation>
    </message>
    <message>
        <source>Step ▶</source>
        <translation>Paso ▶</translation>
    </message>
    <message>
        <source>Pause to take a step apart: it is worked out for one step at a time, not for every frame.</source>
        <translation>Pausa para ver un paso por dentro: se calcula paso a paso, no en cada fotograma.</translation>
    </message>
    <message>
        <source>There is no ball to follow.</source>
        <translation>No hay ninguna bola que seguir.</translation>
    </message>
    <message>
        <source>Sub-step %1 of %2: h = %3 s, starting at</source>
        <translation>Subpaso %1 de %2: h = %3 s, empezando en</translation>
    </message>
    <message>
        <source>The step starts: h = %1 s</source>
        <translation>Empieza el paso: h = %1 s</translation>
    </message>
    <message>
        <source>Force: %1 adds its acceleration</source>
        <translation>Fuerza: %1 suma su aceleración</translation>
    </message>
    <message>
        <source>its own part: (%1, %2) px/s²</source>
        <translation>su parte: (%1, %2) px/s²</translation>
    </message>
    <message>
        <source>Acceleration: all the forces added up</source>
        <translation>Aceleración: todas las fuerzas sumadas</translation>
    </message>
    <message>
        <source>Acceleration k%1, at a trial state (Runge-Kutta)</source>
        <translation>Aceleración k%1, en un estado de prueba (Runge-Kutta)</translation>
    </message>
    <message>
        <source>no force is switched on: the acceleration stays 0</source>
        <translation>no hay ninguna fuerza activada: la aceleración sigue en 0</translation>
    </message>
    <message>
        <source>Velocity changes</source>
        <translation>Cambia la velocidad</translation>
    </message>
    <message>
        <source>Position moves</source>
        <translation>Se mueve la posición</translation>
    </message>
    <message>
        <source>with the %1 accelerations above, weighted 1, 2, 2, 1</source>
        <translation>con las %1 aceleraciones de arriba, con pesos 1, 2, 2, 1</translation>
    </message>
    <message>
        <source>no wall touched: nothing changed</source>
        <translation>no se ha tocado ninguna pared: nada ha cambiado</translation>
    </message>
    <message>
        <source>nothing changed for this ball</source>
        <translation>nada ha cambiado para esta bola</translation>
    </message>
    <message>
        <source>Detection: which balls touch?</source>
        <translation>Detección: ¿qué bolas se tocan?</translation>
    </message>
    <message>
        <source>ball %1 and ball %2</source>
        <translation>bola %1 y bola %2</translation>
    </message>
    <message>
        <source>no ball touches ball %1 (%2 touching pairs in all)</source>
        <translation>ninguna bola toca la bola %1 (%2 pares en contacto en total)</translation>
    </message>
    <message>
        <source>touching: %1</source>
        <translation>en contacto: %1</translation>
    </message>
    <message>
        <source>Response with ball %1: the velocities change</source>
        <translation>Respuesta con la bola %1: cambian las velocidades</translation>
    </message>
    <message>
        <source>they are moving apart already: no change</source>
        <translation>ya se están separando: nada cambia</translation>
    </message>
    <message>
        <source>Δvx = %1 px/s, Δvy = %2 px/s</source>
        <translation>Δvx = %1 px/s, Δvy = %2 px/s</translation>
    </message>
    <message>
        <source>Push-apart from ball %1: out of each other</source>
        <translation>Separación de la bola %1: una fuera de la otra</translation>
    </message>
    <message>
        <source>overlap %1 px; Δx = %2 px, Δy = %3 px</source>
        <translation>solapamiento %1 px; Δx = %2 px, Δy = %3 px</translation>
    </message>
    <message>
        <source>Check: the script&apos;s step against the engine&apos;s (C++)</source>
        <translation>Comprobación: el paso del script frente al del motor (C++)</translation>
    </message>
    <message>
        <source>matches the engine bit for bit</source>
        <translation>coincide con el motor bit a bit</translation>
    </message>
    <message>
        <source>differs from the engine by Δx = %1, Δy = %2 px, Δvx = %3, Δvy = %4 px/s</source>
        <translation>difiere del motor en Δx = %1, Δy = %2 px, Δvx = %3, Δvy = %4 px/s</translation>
    </message>
    <message>
        <source>One step, taken apart</source>
        <translation>Un paso, por dentro</translation>
    </message>
    <message>
        <source>Ball %1, step %2 → %3, in the order the JavaScript runs it. Changed values are highlighted.</source>
        <translation>Bola %1, paso %2 → %3, en el orden en que lo ejecuta el JavaScript. Los valores que cambian están resaltados.</translation>
    </message>
</context>
<context>
    <name>forcelab::StopwatchDock</name>
    <message>
        <source>Stopwatch</source>
        <translation>Cronómetro</translation>
    </message>
    <message>
        <source>by hand</source>
        <translation>a mano</translation>
    </message>
    <message>
        <source>on the event</source>
        <translation>con el evento</translation>
    </message>
    <message>
        <source>Start the stopwatch</source>
        <translation>Poner en marcha el cronómetro</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Iniciar</translation>
    </message>
    <message>
        <source>after events:</source>
        <translation>tras eventos:</translation>
    </message>
    <message>
        <source>Stop the stopwatch</source>
        <translation>Parar el cronómetro</translation>
    </message>
    <message>
        <source>Events before the stopwatch stops</source>
        <translation>Eventos antes de que se pare el cronómetro</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Parar</translation>
    </message>
    <message>
        <source>a bounce (moving down, then up)</source>
        <translation>un rebote (bajando y luego subiendo)</translation>
    </message>
    <message>
        <source>the top of a flight</source>
        <translation>lo más alto de un vuelo</translation>
    </message>
    <message>
        <source>crossing the line x =</source>
        <translation>cruzar la línea x =</translation>
    </message>
    <message>
        <source>crossing the line y =</source>
        <translation>cruzar la línea y =</translation>
    </message>
    <message>
        <source>a full turn round the centre</source>
        <translation>una vuelta completa alrededor del centro</translation>
    </message>
    <message>
        <source>Event</source>
        <translation>Evento</translation>
    </message>
    <message>
        <source>Line position</source>
        <translation>Posición de la línea</translation>
    </message>
    <message>
        <source>Line at</source>
        <translation>Línea en</translation>
    </message>
    <message>
        <source>Ball watched</source>
        <translation>Bola observada</translation>
    </message>
    <message>
        <source>Ball</source>
        <translation>Bola</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <source>Arm</source>
        <translation>Armar</translation>
    </message>
    <message>
        <source>Waiting…</source>
        <translation>Esperando…</translation>
    </message>
    <message>
        <source>Start again</source>
        <translation>Empezar de nuevo</translation>
    </message>
    <message>
        <source>%1 s</source>
        <translation>%1 s</translation>
    </message>
    <message>
        <source>Last times: %1</source>
        <translation>Últimos tiempos: %1</translation>
    </message>
</context>
<context>
    <name>forcelab::StudentCodeDock</name>
    <message>
        <source>Your Code</source>
        <translation>Tu código</translation>
    </message>
    <message>
        <source>Rewrite:</source>
        <translation>Reescribir:</translation>
    </message>
    <message>
        <source>JavaScript file to rewrite</source>
        <translation>Archivo JavaScript que reescribir</translation>
    </message>
    <message>
        <source>The stage&apos;s code, one file per rule. Pick one and write your own version.</source>
        <translation>El código de la etapa, un archivo por regla. Elige uno y escribe tu propia versión.</translation>
    </message>
    <message>
        <source>Your JavaScript</source>
        <translation>Tu JavaScript</translation>
    </message>
    <message>
        <source>Run beside the reference</source>
        <translation>Ejecutar junto a la referencia</translation>
    </message>
    <message>
        <source>Runs your version in place of the course&apos;s, beside the reference (Ctrl+Return)</source>
        <translation>Ejecuta tu versión en lugar de la del curso, junto a la referencia (Ctrl+Return)</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Parar</translation>
    </message>
    <message>
        <source>Takes your code off the canvas</source>
        <translation>Quita tu código del lienzo</translation>
    </message>
    <message>
        <source>Back to the course&apos;s file</source>
        <translation>Volver al archivo del curso</translation>
    </message>
    <message>
        <source>Throws away your changes to this file</source>
        <translation>Descarta tus cambios en este archivo</translation>
    </message>
    <message>
        <source>%1 (yours)</source>
        <translation>%1 (tuyo)</translation>
    </message>
    <message>
        <source>Change the code above, then press Run: your version runs beside the course&apos;s.</source>
        <translation>Cambia el código de arriba y pulsa Ejecutar: tu versión se ejecuta junto a la del curso.</translation>
    </message>
    <message>
        <source>Your changes: %1. Press Run to see them beside the reference.</source>
        <translation>Tus cambios: %1. Pulsa Ejecutar para verlos junto a la referencia.</translation>
    </message>
    <message>
        <source>Your code stopped. %1</source>
        <translation>Tu código se ha detenido. %1</translation>
    </message>
    <message>
        <source>Departs at step %1: your code has %2 balls, the reference %3.</source>
        <translation>Se separa en el paso %1: tu código tiene %2 bolas y la referencia %3.</translation>
    </message>
    <message>
        <source>Departs at step %1 (t = %2 s), ball %3: %4 is %5 in your code and %6 in the reference, %7 apart. Now the balls are up to %8 apart.</source>
        <translation>Se separa en el paso %1 (t = %2 s), bola %3: %4 vale %5 en tu código y %6 en la referencia, una diferencia de %7. Ahora la distancia entre las bolas llega a %8.</translation>
    </message>
    <message>
        <source>Agrees with the reference for all %1 steps so far (x, y, vx and vy to 9 significant digits).</source>
        <translation>Coincide con la referencia en los %1 pasos hasta ahora (x, y, vx y vy con 9 cifras significativas).</translation>
    </message>
</context>
<context>
    <name>forcelab::TimelineBar</name>
    <message>
        <source>Step back: pause and show the world one step dt earlier</source>
        <translation>Paso atrás: pausa y muestra el mundo un paso dt antes</translation>
    </message>
    <message>
        <source>Step: re-run the next recorded step, or take a new one at the latest</source>
        <translation>Paso: vuelve a ejecutar el siguiente paso grabado, o da uno nuevo al final</translation>
    </message>
    <message>
        <source>The recorded past: drag to see the world at any step of it</source>
        <translation>El pasado grabado: arrastra para ver el mundo en cualquiera de sus pasos</translation>
    </message>
    <message>
        <source>Step back</source>
        <translation>Paso atrás</translation>
    </message>
    <message>
        <source>Step forward</source>
        <translation>Paso adelante</translation>
    </message>
    <message>
        <source>Timeline: the recorded steps</source>
        <translation>Línea de tiempo: los pasos grabados</translation>
    </message>
    <message>
        <source>Time shown, of the time recorded</source>
        <translation>Tiempo mostrado, del tiempo grabado</translation>
    </message>
    <message>
        <source>t = %1 s of %2 s</source>
        <translation>t = %1 s de %2 s</translation>
    </message>
</context>
<context>
    <name>forcelab::TraceCheck</name>
    <message>
        <source>Check a Student&apos;s &amp;Trace…</source>
        <translation>Comprobar la &amp;traza de un alumno…</translation>
    </message>
    <message>
        <source>Check a trace a student&apos;s own program wrote (CSV or JSON: step, ball, x, y, vx, vy) against this run: where it first departs, and why</source>
        <translation>Comprueba una traza que escribió el propio programa de un alumno (CSV o JSON: step, ball, x, y, vx, vy) frente a esta ejecución: dónde se separa por primera vez y por qué</translation>
    </message>
    <message>
        <source>Check a Student&apos;s Trace</source>
        <translation>Comprobar la traza de un alumno</translation>
    </message>
    <message>
        <source>Traces (*.csv *.json);;All files (*)</source>
        <translation>Trazas (*.csv *.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>%1: a trace is still being checked; wait for its result</source>
        <translation>%1: todavía se está comprobando una traza; espera a su resultado</translation>
    </message>
    <message>
        <source>%1 cannot be checked: %2</source>
        <translation>%1 no se puede comprobar: %2</translation>
    </message>
    <message>
        <source>%1 agrees with the run at every one of its %2 rows (to step %3, t = %4 s): the largest difference is %5.</source>
        <translation>%1 coincide con la ejecución en sus %2 filas (hasta el paso %3, t = %4 s): la mayor diferencia es %5.</translation>
    </message>
    <message>
        <source>%1 departs from the run at step %2 (t = %3 s), ball %4: %5 is %6 where the run has %7, off by %8.</source>
        <translation>%1 se separa de la ejecución en el paso %2 (t = %3 s), bola %4: %5 vale %6 donde la ejecución tiene %7, una diferencia de %8.</translation>
    </message>
    <message>
        <source>Likely cause: %1. The numbers follow the run with %2: %3</source>
        <translation>Causa probable: %1. Los números siguen la ejecución con %2: %3</translation>
    </message>
    <message>
        <source>No known mistake explains it: %1</source>
        <translation>Ningún error conocido lo explica: %1</translation>
    </message>
    <message>
        <source>The canvas does not go there: step %1 is past the %2 steps it runs to at once.</source>
        <translation>El lienzo no llega hasta ahí: el paso %1 está más allá de los %2 pasos que ejecuta de una vez.</translation>
    </message>
    <message>
        <source>Student&apos;s trace</source>
        <translation>Traza del alumno</translation>
    </message>
    <message>
        <source>student&apos;s ball %1, step %2</source>
        <translation>bola %1 del alumno, paso %2</translation>
    </message>
</context>
</TS>
