"""The local web app (`nl2hltl2plan serve`): FastAPI + a static page; needs the `[web]` extra."""
