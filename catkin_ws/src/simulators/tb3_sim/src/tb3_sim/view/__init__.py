"""What a person looks at: the scene copied out of the world, the top-down renderer, the Qt window and
its box tool. Qt is imported only by the modules that draw."""
