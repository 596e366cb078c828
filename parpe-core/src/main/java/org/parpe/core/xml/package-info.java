/** The parse tree: XML elements, attributes and text with source positions (internal). */
package org.parpe.core.xml;
