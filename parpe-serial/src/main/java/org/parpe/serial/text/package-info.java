/**
 * The servo buses' own words in the user's language: {@link org.parpe.serial.text.SerialMsg}, the
 * keys of {@code SerialMessages*.properties} (the servo set-up and driver's warnings so far; the
 * hardware profile's and the sketch's messages are {@link org.parpe.core.text.Msg}'s). They are
 * formatted when reported, in the language {@link org.parpe.core.text.Lang} has chosen; the
 * {@code bus: } before them stays as it is.
 */
package org.parpe.serial.text;
