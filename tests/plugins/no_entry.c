/* A deliberately broken kernel plugin for the loader tests: a library without the entry. */
int sphkern_something_else(void) { return 1; }
