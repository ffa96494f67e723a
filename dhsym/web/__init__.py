"""The browser page's Python side (docs/web.md): `app.handle` answers the page's requests, run by
Pyodide in the page's web worker; nothing here imports numpy, matplotlib or lxml, which the page
does not load."""
