/**
 * The command line's words in the user's language: {@link org.parpe.cli.text.CliMsg}, the keys of
 * the command line's own messages ({@code CliMessages*.properties}), and the help texts of
 * picocli in German, Spanish and Japanese ({@code Help_*.properties}, keyed as picocli looks them
 * up; English stays in the commands' annotations), with {@link org.parpe.cli.text.HelpKeys} the
 * list of them. The language is chosen by {@link org.parpe.core.text.Lang}. Public API for every
 * picocli command line of PARPE, the IDE's {@code parpe gui} too: picocli's parse errors in the
 * user's language ({@link org.parpe.cli.text.ParseErrors}), {@code --lang} read before picocli
 * parses and the help from a bundle ({@link org.parpe.cli.text.CommandLanguage}).
 */
package org.parpe.cli.text;
