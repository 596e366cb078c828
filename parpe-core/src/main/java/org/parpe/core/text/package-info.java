/**
 * PARPE's words in the user's language, in one place (public API). Every text a user reads comes
 * from a UTF-8 {@code .properties} bundle beside a Java enum of its keys ({@link
 * org.parpe.core.text.Msg} for the loader, the simulator, the servo buses and the export, {@link
 * org.parpe.core.text.DiagramMsg} for the diagrams' words, {@link org.parpe.core.text.EditMsg}
 * for the diagram and section editors' refusals), so a missing key is a compile error. A {@link
 * org.parpe.core.text.Message} is a key with its arguments, formatted in the chosen language only when it is shown; {@link
 * org.parpe.core.text.Lang} chooses the language ({@code --lang}, then {@code LC_ALL},
 * {@code LC_MESSAGES}, {@code LANG}, else English) and holds it for the process; {@link
 * org.parpe.core.text.Pseudo} is the testers' pseudo-language {@code qps} (every text longer and
 * accented, to find layouts that cut a translation off).
 *
 * <p>How to add a language: docs/cli.md, "Translating PARPE". Depends on no other package of
 * PARPE and on nothing but {@code java.util} and {@code java.text}.
 */
package org.parpe.core.text;
